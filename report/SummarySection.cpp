// SPDX-License-Identifier: GPL-3.0-or-later
// The report's summary on page 1: one verdict, and the excitation it rests on. With a record
// as the project's excitation the record's critical peak governs and the enveloped-sine check is
// one labelled secondary line; otherwise the enveloped sine's A_crit(1/T) governs. Every
// sentence is built from what was run (record, scaling, floor filter, outcome, verdicts).

#include "report/CodeStyle.h"
#include "report/ReportSections.h"

namespace kinstab::ui::report {

namespace {

int kineticCount(const std::vector<CodeVerdict>& codes) {
    int n = 0;
    for (const CodeVerdict& v : codes)
        n += v.verdict == Verdict::KineticInstabilityGoverns;
    return n;
}

QString governs(const std::vector<CodeVerdict>& codes, const QString& limit) {
    const int kinetic = kineticCount(codes);
    if (kinetic == 0)
        return QStringLiteral("for every code selected the required top-floor ratio lies below "
                              "%1: member overstress governs, the slab does not slide off before "
                              "the structure reaches its code strength.")
            .arg(limit);
    return QStringLiteral("for %1 of %2 codes the required top-floor ratio reaches %3: kinetic "
                          "instability governs there, and the slab seating must be checked.")
        .arg(kinetic)
        .arg(codes.size())
        .arg(limit);
}

// "margins UBC 1976 4.26, ATC 3-06 3.56": the secondary check in one line.
QString marginList(const std::vector<CodeVerdict>& codes) {
    QStringList parts;
    for (const CodeVerdict& v : codes)
        parts << shortCodeName(v.code) + " " + num(v.margin, 2);
    return parts.join(QStringLiteral(", "));
}

QString filterText(const RecordExcitation& e) {
    return e.floor ? QStringLiteral("through the floor filter of the building (T = %1 s, ζ = %2)")
                         .arg(num(e.floor->period, 3), num(e.floor->damping, 3))
                   : QStringLiteral("driving the slab directly (no floor filter)");
}

// The single run at the project's scaling, beside the critical peak: why "collapsed" there does
// not contradict "overstress governs".
QString asRunText(const RecordExcitation& e, const RecordAnalysis& r, double tstar) {
    const bool asGiven = !e.targetPeak && e.scaleFactor == 1.0;
    const QString at = asGiven ? QStringLiteral("the record as given (scale %1, peak %2 g)")
                                     .arg(num(r.scaleFactor, 1), accelG(r.peak))
                               : QStringLiteral("the record as scaled in the project (factor "
                                                "%1, peak %2 g)")
                                     .arg(num(r.scaleFactor, 4), accelG(r.peak));
    if (r.run.outcome != Outcome::Collapsed)
        return QStringLiteral("At %1 the slab does not fall (%2).")
            .arg(at, qs(outcomeName(r.run.outcome)));
    return QStringLiteral("The slab collapses at %1, at τc = %2 (t = %3 s): that peak lies above "
                          "the critical peak, so the record as it is would slide the slab off. "
                          "The design check does not ask whether this record collapses the slab, "
                          "but whether the structure reaches its code strength first: it compares "
                          "each code's top-floor ratio with the critical peak.")
        .arg(at, num(r.run.tauC, 3), num(r.run.tauC * tstar, 2));
}

void addRecordVerdict(ReportDocument& doc, const Project& p, const ReportAnalysis& a) {
    const RecordAnalysis& r = *a.record;
    const RecordExcitation& e = *p.record;
    const RecordCriticalScale& c = *r.critical;
    doc.addParagraph(
        QStringLiteral("Verdict basis: the recorded excitation. The project's excitation is the "
                       "record %1, %2, so the verdict rests on the record's critical peak, the "
                       "smallest peak of the scaled motion under the slab that slides the slab "
                       "off, and not on the enveloped sine.")
            .arg(qs(r.ground.name), filterText(e)));
    const QString peak =
        c.peak ? QStringLiteral("%1 g (factor %2 on the record)")
                     .arg(accelG(*c.peak), num(*c.factor, 4))
               : QStringLiteral("beyond the search limit of %1 g").arg(num(p.critical.to, 2));
    const QString limit = c.peak ? QStringLiteral("the critical peak %1 g").arg(accelG(*c.peak))
                                 : QStringLiteral("the search limit");
    doc.addParagraph(
        QStringLiteral("With the project's record the critical peak is %1. ").arg(peak) +
        asRunText(e, r, p.slab.tstar) + " Verdict: " + governs(r.verdicts, limit));
    addVerdictTable(doc, r.verdicts, QStringLiteral("critical peak (g)"));
    if (!a.check.codes.empty()) {
        const CodeVerdict& first = a.check.codes.front();
        const int kinetic = kineticCount(a.check.codes);
        const QString outcome =
            kinetic == 0 ? QStringLiteral("overstress governs for every code")
                         : QStringLiteral("kinetic instability governs for %1 of %2 codes")
                               .arg(kinetic)
                               .arg(a.check.codes.size());
        doc.addParagraph(
            QStringLiteral("Secondary check, enveloped sine (for comparison; not the verdict): "
                           "A_crit = %1 g at f = 1/T = %2 Hz, margins %3; %4. See the section "
                           "\"Design check with the enveloped sine\".")
                .arg(accelG(first.aCrit, QStringLiteral("> limit")), num(first.frequencyHz, 3),
                     marginList(a.check.codes), outcome),
            true);
    }
}

} // namespace

bool recordGoverns(const Project& p, const ReportAnalysis& a) {
    return p.record && a.record && a.record->critical && !a.record->verdicts.empty();
}

void addSummary(ReportDocument& doc, const Project& p, const ReportAnalysis& a) {
    if (a.check.codes.empty()) return;
    doc.addHeading(QStringLiteral("Summary"));
    if (recordGoverns(p, a)) return addRecordVerdict(doc, p, a);
    doc.addParagraph(
        QStringLiteral(
            "Verdict basis: the enveloped sine (Furgerson 1980, ch. IV), the project's "
            "excitation. The check compares, for each code, the top-floor force ratio "
            "F_top/w_top with A_crit(f), the smallest peak floor acceleration (in g) that slides "
            "the slab off its walls at the building frequency f = 1/T: ") +
        governs(a.check.codes, QStringLiteral("A_crit")));
    addVerdictTable(doc, a);
}

} // namespace kinstab::ui::report
