// SPDX-License-Identifier: GPL-3.0-or-later
// The report's study section (docs/studies.md): the project's record suite and parameter sets,
// and per parameter set the lognormal collapse fragility fitted to the records' critical
// intensities - median and dispersion with their bootstrap bounds, as a table and as a curve with
// its bounds and the empirical points. The rows come from the project's results file when it has
// one, else the study runs here, on one thread (a report is not a cluster job: see the limit).

#include "core/io/StudyResults.h"
#include "core/io/StudySpecJson.h"
#include "core/records/RecordReader.h"
#include "core/study/Fragility.h"
#include "core/study/StudyRecords.h"
#include "core/study/StudyRowsMatch.h"
#include "core/study/StudyRunner.h"
#include "core/study/StudySpec.h"
#include "report/CurveFigure.h"
#include "report/PlotFrame.h"
#include "report/RecordSources.h"
#include "report/ReportError.h"
#include "report/ReportSections.h"

#include <QFileInfo>

#include <algorithm>
#include <cmath>

namespace kinstab::report {

namespace {

// A report runs a study without results on one thread while the user waits: a few hundred
// cases take minutes. Larger studies are run with `kinstab-cli study` (sharded if need be) and
// their results named in the project.
constexpr std::size_t kMaxReportStudyCases = 500;

const QColor kFit(40, 90, 160), kBound(120, 150, 200), kPoint(200, 40, 40);

std::vector<StudyRow> rowsOfRun(StudySpec spec) {
    const std::size_t cases = studyCaseCount(spec);
    if (cases > kMaxReportStudyCases)
        throw ReportError("study: " + std::to_string(cases) +
                          " cases, more than the report runs itself (" +
                          std::to_string(kMaxReportStudyCases) +
                          "); run `kinstab-cli study` and name its output in study.results");
    std::vector<StudyRow> rows;
    try {
        loadStudyRecords(spec);
        rows = runStudyRows(spec, {});
    } catch (const std::exception& e) {
        throw ReportError(std::string("study: ") + e.what());
    }
    return rows;
}

// Results of another study than the file now says (edited after the run) are refused, not
// printed as the study's.
std::vector<StudyRow> studyRows(const ProjectStudy& ps, const StudySpec& spec) {
    if (ps.results.empty()) return rowsOfRun(spec);
    std::vector<StudyRow> rows;
    try {
        rows = readStudyRows(ps.results);
    } catch (const StudyRowError& e) {
        throw ReportError("study.results = '" + ps.results + "': " + e.what());
    }
    StudySpec hashed = spec; // the rows' fingerprint is checked against the records' bytes
    try {
        hashStudyRecords(hashed);
    } catch (const StudyError& e) {
        throw ReportError("study.spec = '" + ps.spec + "': " + e.what());
    }
    const std::string dir = QFileInfo(qs(ps.spec)).absolutePath().toStdString();
    if (const std::string m = studyRowsMismatch(hashed, dir, rows); !m.empty())
        throw ReportError("study.results = '" + ps.results + "': not the results of " + ps.spec +
                          " (" + m + "); run the study again or remove study.results");
    return rows;
}

StudySpec studySpec(const ProjectStudy& ps) {
    try {
        return loadStudy(ps.spec);
    } catch (const StudyError& e) {
        throw ReportError("study.spec = '" + ps.spec + "': " + e.what());
    }
}

// "PGA" or "Sa(T = 1 s, ζ = 0.05)": the intensity measure in words, not the file's key.
QString measureLabel(const IntensityMeasure& im) {
    if (im.kind == IntensityMeasure::Kind::Pga) return QStringLiteral("PGA");
    return QStringLiteral("Sa(T = %1 s, ζ = %2)")
        .arg(QString::number(im.period, 'g', 4), QString::number(im.damping, 'g', 3));
}

void recordTable(ReportDocument& doc, const std::vector<StudyRow>& rows) {
    Table t{{"record", "intensity of the record as given (g)"},
            {},
            {3.5, 1.5},
            {Align::Left, Align::Right},
            {}};
    for (const StudyRow& r : rows)
        if (r.set == 0) t.rows.push_back({qs(r.record), accelG(r.recordIntensity)});
    doc.addTable(t);
}

// "0.412 – 0.903", an unbounded upper end as "> " the search's top (too few collapses in some
// resamples to show a median), "—" without a bootstrap.
QString bounds(const std::optional<double>& lo, const std::optional<double>& hi, int digits,
               double top = 0) {
    if (!lo || !hi) return QStringLiteral("—");
    const QString upper = std::isfinite(*hi) ? num(*hi, digits) : "> " + num(top, digits);
    return QStringLiteral("%1 – %2").arg(num(*lo, digits), upper);
}

// The fit's median, marked when it lies beyond every record's search limit.
QString medianCell(const Fragility& f) {
    if (!f.fit) return QStringLiteral("—");
    return accelG(f.fit->median) + (f.medianBeyondSearch ? QStringLiteral(" (extrapolated)") : "");
}

// The spread of the critical intensity over the records that collapse, per set (SLAMMER-style
// suite statistics beside the fit; core/study/Fragility.h RecordStatistics).
void statisticsTable(ReportDocument& doc, const std::vector<Fragility>& sets) {
    Table t{{"set", "collapsed", "censored", "mean (g)", "median (g)", "σ (g)", "mean of ln",
             "σ of ln"},
            {},
            {0.5, 1.0, 1.0, 1.0, 1.0, 1.0, 1.1, 0.9},
            {Align::Left, Align::Right, Align::Right, Align::Right, Align::Right, Align::Right,
             Align::Right, Align::Right},
            {}};
    for (const Fragility& f : sets) {
        const RecordStatistics& s = f.statistics;
        t.rows.push_back({QString::number(f.parameters.set + 1), QString::number(s.collapsed),
                          QString::number(s.censored), accelG(s.meanG, "—"), accelG(s.medianG, "—"),
                          accelG(s.stdG, "—"), num(s.meanLn, 3), num(s.stdLn, 3)});
    }
    doc.addTable(t);
    doc.addParagraph(QStringLiteral(
        "Over the records that collapse the slab: the mean, median and standard deviation "
        "(divisor n − 1) of the critical intensity and of its natural logarithm; censored "
        "records (no collapse up to the search limit) are counted, not averaged. The fit above "
        "uses the censored records too."));
}

void fragilityTable(ReportDocument& doc, const std::vector<Fragility>& sets) {
    Table t{{"set", "μ", "t* (s)", "driving motion", "collapsed", "median (g)", "median bounds (g)",
             "β", "β bounds"},
            {},
            {0.4, 0.6, 0.7, 1.7, 0.9, 0.8, 1.4, 0.6, 1.3},
            {Align::Left, Align::Right, Align::Right, Align::Left, Align::Right, Align::Right,
             Align::Right, Align::Right, Align::Right},
            {}};
    for (const Fragility& f : sets) {
        const StudyRow& r = f.parameters;
        // A block set: its block's mu (— when the base holds it) and no t*.
        const QString mu = !r.block      ? num(r.mu, 3)
                           : r.block->mu ? num(*r.block->mu, 3)
                                         : QStringLiteral("—");
        const QString tstar = r.block ? QStringLiteral("—") : num(r.tstar, 3);
        t.rows.push_back({QString::number(r.set + 1), mu, tstar, qs(studyDriverText(r)),
                          QStringLiteral("%1 of %2").arg(f.collapsed).arg(f.records), medianCell(f),
                          bounds(f.medianLower, f.medianUpper, 3, f.searchTop),
                          f.fit ? num(f.fit->beta, 3) + (f.betaAtBound ? " (at bound)" : "")
                                : QStringLiteral("—"),
                          bounds(f.betaLower, f.betaUpper, 3)});
    }
    doc.addTable(t);
    bool extrapolated = false, unfitted = false;
    for (const Fragility& f : sets) {
        extrapolated = extrapolated || f.medianBeyondSearch;
        unfitted = unfitted || (f.fit && f.fitted < f.resamples);
    }
    if (extrapolated)
        doc.addParagraph(QStringLiteral("\"Extrapolated\": the fitted median lies above every "
                                        "record's search limit, beyond the intensities searched; "
                                        "it is not a finding of the study."),
                         true);
    if (unfitted)
        doc.addParagraph(
            QStringLiteral("Bootstrap resamples with fewer than two distinct collapses "
                           "cannot be fitted; they count as medians beyond the data, "
                           "so an upper bound may be open (\"> the search's top\")."),
            true);
}

CurvePlot fragilityPlot(const Fragility& f, double xhi, const QString& measure) {
    CurvePlot plot{{},
                   0,
                   xhi,
                   0,
                   1.0,
                   QStringLiteral("%1 (g)").arg(measure),
                   QStringLiteral("probability of collapse")};
    QList<QPointF> mid, lo, hi;
    for (const FragilityCurvePoint& c : f.curve) {
        mid.append(QPointF(c.intensity, c.probability));
        if (c.lower) lo.append(QPointF(c.intensity, *c.lower));
        if (c.upper) hi.append(QPointF(c.intensity, *c.upper));
    }
    plot.curves.push_back({mid, kFit, QStringLiteral("lognormal fit"), 0.3});
    if (!lo.isEmpty()) {
        plot.curves.push_back({lo, kBound, QStringLiteral("bootstrap bounds"), 0.15});
        plot.curves.push_back({hi, kBound, QString(), 0.15});
    }
    return plot;
}

// The curve and bounds by paintCurves; the empirical points on top, in the same frame.
void paintFragility(QPainter& pa, const QRectF& area, const CurvePlot& plot,
                    const std::vector<FragilityPoint>& points) {
    paintCurves(pa, area, plot);
    const PlotFrame fr(area, plot.xlo, plot.xhi, plot.ylo, plot.yhi);
    const double r = 0.6 * fr.scale().unit();
    pa.setPen(fr.scale().pen(kPoint, 0.15));
    pa.setBrush(kPoint);
    for (const FragilityPoint& q : points)
        pa.drawEllipse(fr.map(q.intensity, q.probability), r, r);
    pa.setBrush(Qt::NoBrush);
}

void fragilityFigures(ReportDocument& doc, const std::vector<Fragility>& sets,
                      const QString& measure) {
    double xhi = 0;
    for (const Fragility& f : sets) {
        for (const FragilityCurvePoint& c : f.curve)
            xhi = std::max(xhi, c.intensity);
        for (const FragilityPoint& q : f.points)
            xhi = std::max(xhi, q.intensity);
    }
    if (!(xhi > 0)) return;
    for (const Fragility& f : sets) {
        if (!f.fit) continue;
        const CurvePlot plot = fragilityPlot(f, xhi, measure);
        const std::vector<FragilityPoint> points = f.points;
        const QString of = f.parameters.block
                               ? QStringLiteral("Overturning fragility of set %1 (block %2)")
                                     .arg(f.parameters.set + 1)
                                     .arg(qs(studyBlockText(*f.parameters.block)))
                               : QStringLiteral("Collapse fragility of set %1 (μ = %2, t* = %3 s)")
                                     .arg(f.parameters.set + 1)
                                     .arg(num(f.parameters.mu, 3), num(f.parameters.tstar, 3));
        doc.addFigure(
            {[plot, points](QPainter& pa, const QRectF& a) { paintFragility(pa, a, plot, points); },
             0.42,
             of + QStringLiteral(": the fitted lognormal curve, its bootstrap bounds and the "
                                 "records' critical intensities (points).")});
    }
}

} // namespace

void addStudySection(ReportDocument& doc, const Project& p, const ReportAnalysis&) {
    if (!p.study) return;
    const StudySpec spec = studySpec(*p.study);
    const std::vector<StudyRow> rows = studyRows(*p.study, spec);
    const BootstrapSettings boot; // the defaults of `kinstab-cli fragility`
    const std::vector<Fragility> sets = studyFragility(rows, boot);
    const QString measure = measureLabel(spec.intensity);
    // A block study (docs/studies.md, "A block instead of the slab") asks for overturning.
    const QString model =
        spec.block
            ? QStringLiteral("the block (%1) overturns; a record that does not overturn it")
                  .arg(qs(studyBlockText(*spec.block)))
            : QStringLiteral("the slab slides off; a record that does not collapse the slab");
    doc.addSection(
        spec.block ? QStringLiteral("Study: overturning fragility of a block over a record suite")
                   : QStringLiteral("Study: collapse fragility over a record suite"));
    doc.addParagraph(
        QStringLiteral(
            "The study %1 (file %2) runs each of its %3 records for each of its %4 parameter "
            "sets and finds the smallest intensity (%5) of the scaled record at which %10 up to "
            "the search limit counts as censored there. %6 Per parameter set the critical "
            "intensities are fitted by a "
            "lognormal fragility (median and dispersion β by maximum likelihood), with %7 % "
            "bounds from %8 bootstrap resamples over the records (seed %9).")
            .arg(qs(spec.name), QFileInfo(qs(p.study->spec)).fileName())
            .arg(spec.records.size())
            .arg(studyParameterSets(spec))
            .arg(measure, p.study->results.empty()
                              ? QStringLiteral("The cases ran for this report.")
                              : QStringLiteral("The rows are read from %1.")
                                    .arg(QFileInfo(qs(p.study->results)).fileName()))
            .arg(num(100 * boot.level, 0))
            .arg(boot.resamples)
            .arg(boot.seed)
            .arg(model));
    doc.addHeading(QStringLiteral("Records"), 2);
    recordTable(doc, rows);
    doc.addHeading(QStringLiteral("Fragility per parameter set"), 2);
    fragilityTable(doc, sets);
    doc.addHeading(QStringLiteral("Critical intensity per parameter set"), 2);
    statisticsTable(doc, sets);
    fragilityFigures(doc, sets, measure);
}

QStringList studyCitations(const Project& p) {
    QStringList refs;
    if (!p.study) return refs;
    StudySpec spec;
    try {
        spec = loadStudy(p.study->spec);
    } catch (const StudyError&) {
        return refs; // the study section has said why
    }
    for (const StudyRecord& r : spec.records) {
        try {
            refs << recordCitation(readRecord(r.file), qs(r.file));
        } catch (const std::exception&) {
            refs << QStringLiteral("%1 (the file could not be read)").arg(qs(r.label));
        }
    }
    return refs;
}

} // namespace kinstab::report
