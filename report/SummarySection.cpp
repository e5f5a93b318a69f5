// SPDX-License-Identifier: GPL-3.0-or-later
// The report's summary on page 1: the project's assessment (core/assessment) as it is, every
// check with its margin and verdict and the governing one, and what each basis rests on. Every
// sentence is built from the checks that ran (their model, excitation and comparisons); no
// verdict is composed here.

#include "report/CodeStyle.h"
#include "report/ReportSections.h"

#include <algorithm>
#include <set>

namespace kinstab::report {

namespace {

QString marginCell(const Comparison& x) {
    return qs(marginText(x));
}

QString basisPhrase(CheckBasis b) {
    switch (b) {
    case CheckBasis::Sine:
        return QStringLiteral("the enveloped sine (Furgerson 1980, ch. IV–V)");
    case CheckBasis::Planar:
        return QStringLiteral("the planar slab (Furgerson 1980, ch. VI)");
    case CheckBasis::Record:
        return QStringLiteral("the project's record");
    case CheckBasis::Floors:
        return QStringLiteral("the building's floor motions");
    case CheckBasis::Risk:
        return QStringLiteral("the study's fragilities against the site's hazard curve");
    case CheckBasis::Block:
        return QStringLiteral("the free-standing blocks on the building's floors");
    }
    return {};
}

std::vector<CheckBasis> basesOf(const Assessment& a) {
    std::vector<CheckBasis> out;
    for (const Check& c : a.checks)
        if (std::find(out.begin(), out.end(), c.basis) == out.end()) out.push_back(c.basis);
    return out;
}

const Check* firstOf(const Assessment& a, CheckBasis b) {
    for (const Check& c : a.checks)
        if (c.basis == b) return &c;
    return nullptr;
}

// What one basis rests on, from its first check (every check of a basis shares model and
// excitation).
QString basisText(const Assessment& a, CheckBasis b) {
    const Check& c = *firstOf(a, b);
    const Comparison& x = c.comparisons.front();
    if (b == CheckBasis::Risk) // each set has its own fragility: the model is per check
        return QStringLiteral("%1.setK: the collapse fragility of the study's parameter set K "
                              "(section \"Risk\"); excitation: %2; %3: %4 against %5.")
            .arg(qs(checkBasisName(b)), qs(c.excitation), qs(x.intensity), qs(x.demandName),
                 qs(x.capacityName));
    if (b == CheckBasis::Block) // each block is its own model: the model is per check
        return QStringLiteral("%1.NAME.*: the free-standing block NAME rocking on its level "
                              "(section \"Free-standing blocks\"); excitation: %2; %3: %4 "
                              "against the ground PGA at which it overturns, and the code's "
                              "floor formula against its critical floor peak.")
            .arg(qs(checkBasisName(b)), qs(c.excitation), qs(x.intensity), qs(x.demandName));
    QString s = QStringLiteral("%1.*: %2; excitation: %3; %4: %5 against %6.")
                    .arg(qs(checkBasisName(b)), qs(c.model), qs(c.excitation), qs(x.intensity),
                         qs(x.demandName), qs(x.capacityName));
    if (b == CheckBasis::Floors)
        s += QStringLiteral(" Each floor check also compares the code's own floor formula (%1 "
                            "against the %2); where it fails while the ground comparison holds, "
                            "it governs the check.")
                 .arg(qs(c.comparisons.back().demandName), qs(c.comparisons.back().capacityName));
    return s;
}

QString countText(const Assessment& a) {
    int failing = 0;
    QStringList ids;
    for (const Check& c : a.checks)
        if (!c.holds) ++failing, ids << qs(c.id);
    if (failing == 0) return QStringLiteral("Every check holds.");
    return QStringLiteral("%1 of %2 checks do not hold: %3.")
        .arg(failing)
        .arg(a.checks.size())
        .arg(ids.join(QStringLiteral(", ")));
}

// The single run at the project's scaling, beside the critical peak: why "collapsed" there does
// not contradict a check that holds.
QString asRunText(const Project& p, const RecordAnalysis& r) {
    const RecordExcitation& e = *p.record;
    const bool asGiven = !e.targetPeak && e.scaleFactor == 1.0;
    const QString at =
        asGiven
            ? QStringLiteral("the record as given (peak %1 g under the slab)").arg(accelG(r.peak))
            : QStringLiteral("the record as scaled in the project (factor "
                             "%1, peak %2 g under the slab)")
                  .arg(num(r.scaleFactor, 4), accelG(r.peak));
    if (r.run.outcome != Outcome::Collapsed)
        return QStringLiteral("At %1 the slab does not fall (%2).")
            .arg(at, qs(outcomeName(r.run.outcome)));
    return QStringLiteral("At %1 the slab falls (τc = %2, t = %3 s): that peak lies above the "
                          "critical peak. The record checks ask whether the structure reaches "
                          "its code strength first, so they compare each code's top-floor ratio "
                          "with the critical peak, not with this run.")
        .arg(at, num(r.run.tauC, 3), num(r.run.tauC * p.slab.tstar, 2));
}

} // namespace

void addChecksTable(ReportDocument& doc, const Assessment& a) {
    // One line a check, so that page 1 holds them all: what each compares is said below the table.
    // The unit goes in the header while every check is in g; risk checks (annual rates) put it in
    // each cell instead.
    const bool allG = std::all_of(a.checks.begin(), a.checks.end(),
                                  [](const Check& c) { return c.governing().unit == "g"; });
    const bool wideIds = hasBasis(a, CheckBasis::Block);
    Table t{{"check", allG ? "demand (g)" : "demand", allG ? "capacity (g)" : "capacity", "margin",
             "verdict"},
            {},
            // Block ids carry the block's name: a wider id column keeps each on one line.
            {wideIds ? 2.6 : 1.9, allG ? 0.8 : 1.35, allG ? 0.9 : 1.35, 0.7,
             (allG ? 3.0 : 2.6) - (wideIds ? 0.7 : 0.0)},
            {Align::Left, Align::Right, Align::Right, Align::Right, Align::Left},
            {}};
    for (std::size_t k = 0; k < a.checks.size(); ++k) {
        const Check& c = a.checks[k];
        const Comparison& x = c.governing();
        const auto cell = [&x, allG](double v) {
            return qs(quantityText(x, v)) + (allG ? QString() : " " + qs(x.unit));
        };
        if (a.governing == k) t.boldRows.push_back(static_cast<int>(t.rows.size()));
        t.rows.push_back({qs(c.id), cell(x.demand),
                          x.capacity ? cell(*x.capacity) : QStringLiteral("none"), marginCell(x),
                          qs(c.verdict)});
    }
    doc.addTable(t);
}

void addSummary(ReportDocument& doc, const Project& p, const ReportAnalysis& a) {
    const Assessment& s = a.assessment;
    const Check* g = s.governingCheck();
    if (!g) return;
    doc.addHeading(QStringLiteral("Summary"));
    QStringList bases;
    for (CheckBasis b : basesOf(s))
        bases << basisPhrase(b);
    doc.addParagraph(
        QStringLiteral("The project implies %1 checks, on %2; each compares a demand with a "
                       "capacity in one intensity, margin = capacity / demand. %3")
            .arg(s.checks.size())
            .arg(bases.join(QStringLiteral("; ")), countText(s)));
    doc.addParagraph(
        QStringLiteral("Governing check: %1, margin %2: %3 (%4).")
            .arg(qs(g->id), marginCell(g->governing()), qs(g->verdict), qs(s.governingReason)));
    addChecksTable(doc, s);
    for (CheckBasis b : basesOf(s))
        doc.addParagraph(basisText(s, b), true);
    for (const std::string& n : s.notes)
        doc.addParagraph(qs(n), true);
    if (p.record && a.record) doc.addParagraph(asRunText(p, *a.record), true);
}

} // namespace kinstab::report
