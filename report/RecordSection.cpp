// SPDX-License-Identifier: GPL-3.0-or-later
// The report's record section (docs/theory.md §7; docs/user-guide.md): where the record comes from,
// how it was scaled and filtered, what it looks like in time and frequency (the paper's Figs.
// 25-27), what it does to the slab, and the critical peak against the code ratios.

#include "core/excitation/FourierSpectrum.h"
#include "report/CurveFigure.h"
#include "report/DecimatedSeries.h"
#include "report/ReportSections.h"

#include <QFileInfo>

#include <algorithm>
#include <cmath>

namespace kinstab::report {

namespace {

const QColor kGround(40, 90, 160), kFloor(200, 40, 40), kGrey(110, 110, 110);

QList<QPointF> scaled(QList<QPointF> pts, double factor) {
    for (QPointF& q : pts)
        q.setY(q.y() * factor);
    return pts;
}

void provenanceTable(ReportDocument& doc, const Project& p, const RecordAnalysis& r) {
    const Accelerogram& g = r.ground;
    const SignedPeak pk = g.peak();
    const RecordExcitation& e = *p.record;
    Table t{{"item", "value"}, {}, {1.4, 3.6}, {Align::Left, Align::Left}, {}};
    t.rows.push_back({"record", qs(g.name)});
    t.rows.push_back({"station, component", qs(g.station) + ", " + qs(g.component)});
    t.rows.push_back({"file", QFileInfo(qs(e.file)).fileName() + " (" + qs(g.format) + ")"});
    t.rows.push_back({"points, dt", QStringLiteral("%1 at %2 s (%3 s)")
                                        .arg(g.size())
                                        .arg(num(g.dt, 4), num(g.duration(), 2))});
    t.rows.push_back({"file units", qs(accelUnitName(g.fileUnit))});
    t.rows.push_back(
        {"ground peak", QStringLiteral("%1 g at t = %2 s").arg(accelG(pk.value), num(pk.time, 2))});
    t.rows.push_back(
        {"floor filter", e.floor ? QStringLiteral("T = %1 s, ζ = %2 (paper eq. 6, Nigam–Jennings)")
                                       .arg(num(e.floor->period, 3), num(e.floor->damping, 3))
                                 : QStringLiteral("none: the record drives the slab directly")});
    t.rows.push_back({"scaling", QStringLiteral("peak %1 g of the motion under the slab (factor "
                                                "%2 on its own peak %3 g)")
                                     .arg(accelG(r.peak), num(r.scaleFactor, 4),
                                          accelG(std::abs(r.motion.peak().value)))});
    doc.addTable(t);
}

void timeFigure(ReportDocument& doc, const RecordAnalysis& r, bool floor) {
    CurvePlot plot;
    const double peak = std::max(std::abs(r.ground.peak().value), r.peak);
    plot.xlo = 0, plot.xhi = r.motion.duration(), plot.ylo = -1.1 * peak, plot.yhi = 1.1 * peak;
    plot.xLabel = QStringLiteral("time t (s)");
    plot.yLabel = QStringLiteral("acceleration (g)");
    plot.curves.push_back(
        {decimatedSeries(r.ground.samples, r.ground.dt, 800), kGround, "ground", 0.12});
    if (floor || r.scaleFactor != 1.0)
        plot.curves.push_back(
            {scaled(decimatedSeries(r.motion.samples, r.motion.dt, 800), r.scaleFactor), kFloor,
             floor ? "floor, scaled" : "scaled", 0.12});
    doc.addFigure({[plot](QPainter& pa, const QRectF& a) { paintCurves(pa, a, plot); }, 0.42,
                   QStringLiteral("Acceleration of the ground record and of the scaled motion "
                                  "under the slab.")});
}

void spectrumFigure(ReportDocument& doc, const RecordAnalysis& r, bool floor) {
    const double fMax = std::min(15.0, 0.5 / r.ground.dt);
    const auto curve = [fMax](const std::vector<double>& x, double dt) {
        const AmplitudeSpectrum s = amplitudeSpectrum(x, dt);
        QList<QPointF> pts;
        for (std::size_t k = 0; k < s.frequency.size() && s.frequency[k] <= fMax; ++k)
            pts.append(QPointF(s.frequency[k], s.amplitude[k]));
        return pts;
    };
    CurvePlot plot{{}, 0, fMax, 0, 1.05, "frequency (Hz)", "|X| / max |X|"};
    plot.curves.push_back({curve(r.ground.samples, r.ground.dt), kGround, "ground", 0.12});
    if (floor) {
        // Same length as the ground record, so both spectra share their bins (Fig. 26).
        const std::vector<double> same(r.motion.samples.begin(),
                                       r.motion.samples.begin() +
                                           static_cast<long>(r.ground.samples.size()));
        plot.curves.push_back({curve(same, r.ground.dt), kFloor, "floor", 0.15});
    }
    doc.addFigure({[plot](QPainter& pa, const QRectF& a) { paintCurves(pa, a, plot); }, 0.42,
                   QStringLiteral("Fourier amplitude spectra normalized to their largest "
                                  "component (Figs. 25–26).")});
}

void envelopeFigure(ReportDocument& doc, const RecordAnalysis& r) {
    const double d = r.motion.duration();
    CurvePlot plot{{}, 0, d, 0, 1.1 * r.peak, "time t (s)", "|a| (g)"};
    plot.curves.push_back(
        {scaled(decimatedSeries(r.motion.samples, r.motion.dt, 800, true), r.scaleFactor), kGrey,
         "|motion under the slab|", 0.1});
    QList<QPointF> env;
    for (int i = 0; i <= 400; ++i)
        env.append(QPointF(d * i / 400.0, r.scaleFactor * r.fit->at(d * i / 400.0)));
    plot.curves.push_back({env, kFloor,
                           QStringLiteral("envelope α = %1, β = %2 1/s")
                               .arg(num(r.fit->alpha, 3), num(r.fit->beta, 3)),
                           0.3});
    doc.addFigure({[plot](QPainter& pa, const QRectF& a) { paintCurves(pa, a, plot); }, 0.42,
                   QStringLiteral("|Acceleration| under the slab with the fitted envelope "
                                  "c (exp(−αt) − exp(−βt)) (Fig. 27).")});
}

void runTable(ReportDocument& doc, const Project& p, const RecordAnalysis& r) {
    const SlabResult& s = r.run;
    const bool collapsed = s.outcome == Outcome::Collapsed;
    Table t{{"result", "value"}, {}, {2.5, 2.5}, {Align::Left, Align::Right}, {}};
    const bool asGiven = !p.record->targetPeak && p.record->scaleFactor == 1.0;
    t.rows.push_back(
        {asGiven ? QStringLiteral("outcome at the record as given (scale 1.0, peak %1 g)")
                       .arg(accelG(r.peak))
                 : QStringLiteral("outcome at the project's scaling (factor %1, peak %2 g)")
                       .arg(num(r.scaleFactor, 4), accelG(r.peak)),
         qs(outcomeName(s.outcome))});
    t.rows.push_back(
        {"collapse time τc (t = τc t*)",
         collapsed ? QStringLiteral("%1 (%2 s)").arg(num(s.tauC, 3), num(s.tauC * p.slab.tstar, 2))
                   : QStringLiteral("—")});
    t.rows.push_back({"max |δ| (bearing limit %1)", num(s.maxAbsDelta, 4)});
    t.rows.back()[0] = t.rows.back()[0].arg(num(p.slab.slab.limit, 2));
    t.rows.push_back({"slip intervals", QString::number(s.slipIntervals)});
    const RecordCriticalScale& c = *r.critical;
    t.rows.push_back(
        {"critical peak (smallest peak that collapses)",
         c.peak ? QStringLiteral("%1 g (factor %2)").arg(accelG(*c.peak), num(*c.factor, 4))
                : QStringLiteral("> %1 g").arg(num(p.critical.to, 2))});
    t.rows.push_back({"slab runs of the search", QString::number(c.runs)});
    t.boldRows = {0, 4};
    doc.addTable(t);
    if (collapsed && c.peak)
        doc.addParagraph(QStringLiteral("The slab collapses at the record's peak of %1 g because "
                                        "it exceeds the critical peak %2 g. The record checks "
                                        "compare each code's top-floor ratio with the critical "
                                        "peak, not with this run.")
                             .arg(accelG(r.peak), accelG(*c.peak)),
                         true);
}

} // namespace

void addRecordSection(ReportDocument& doc, const Project& p, const ReportAnalysis& a) {
    if (!a.record || !p.record) return;
    const RecordAnalysis& r = *a.record;
    const bool floor = p.record->floor.has_value();
    doc.addSection(QStringLiteral("Recorded excitation"));
    // Every clause from what ran: the record analysis runs the 1-DOF slab with the exact solver
    // (core/sweep/RecordAnalysis refuses any other), whatever the project's model.
    const QString model =
        p.model == ModelKind::Planar
            ? QStringLiteral("the 1-DOF slab (the record analysis runs the 1-DOF model; the "
                             "project's planar model gives the enveloped-sine sections)")
            : QStringLiteral("the 1-DOF slab");
    const QString filter =
        floor ? QStringLiteral("The ground record passes through the floor filter, the absolute "
                               "acceleration of a damped linear oscillator of period T = %1 s and "
                               "damping ζ = %2 (the paper's eq. 6); its output drives the slab.")
                    .arg(num(p.record->floor->period, 3), num(p.record->floor->damping, 3))
              : QStringLiteral("No floor filter: the ground record drives the slab directly.");
    const QString scaling =
        p.record->targetPeak
            ? QStringLiteral("scaled to the target peak %1 g").arg(num(*p.record->targetPeak, 4))
            : (p.record->scaleFactor == 1.0
                   ? QStringLiteral("as given (scale 1.0)")
                   : QStringLiteral("scaled by the factor %1").arg(num(p.record->scaleFactor, 4)));
    doc.addParagraph(
        QStringLiteral(
            "The project's excitation is a recorded accelerogram instead of the enveloped sine: "
            "linearly interpolated between samples, zero after its end, driving %1 with the "
            "event-driven exact solver (exact for piecewise-linear input). %2 The single run "
            "below uses the motion %3; the critical peak is the smallest peak of the scaled "
            "motion that slides the slab off (a scan in steps of %4 g refined by bisection to "
            "%5 g, since γc need not grow with the scale). The record checks (record.CODE on "
            "page 1) compare each code's top-floor ratio with the critical peak; the sections on "
            "the enveloped sine give the sine checks.")
            .arg(model, filter, scaling, num(p.critical.scanStep, 3),
                 num(p.critical.tolerance, 7)));
    provenanceTable(doc, p, r);
    timeFigure(doc, r, floor);
    spectrumFigure(doc, r, floor);
    if (r.fit) envelopeFigure(doc, r);
    doc.addHeading(QStringLiteral("Single run and critical peak"), 2);
    runTable(doc, p, r);
    if (!r.verdicts.empty())
        doc.addParagraph(QStringLiteral("Each code's top-floor ratio against the record's "
                                        "critical peak: the record.CODE checks of the assessment "
                                        "on page 1."));
}

} // namespace kinstab::report
