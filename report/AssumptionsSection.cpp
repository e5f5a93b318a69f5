// SPDX-License-Identifier: GPL-3.0-or-later
// "Assumptions and limitations": the idealizations behind the numbers of this report, generated
// from the project so that only those that apply are listed (Furgerson 1980, ch. IV-VI: rigid
// bodies, Coulomb friction, enveloped-sine floor motion at the building frequency).
#include "report/ReportSections.h"

namespace kinstab::report {

namespace {

QStringList slabAssumptions(const Project& p) {
    const Slab1DCase& c = p.slab;
    QStringList out;
    out << QStringLiteral("The slab and the walls are rigid; the slab rests on the walls and is "
                          "held only by friction (no connection, dowel or restraint).");
    out << QStringLiteral("Friction is Coulomb friction with one constant coefficient μ = %1 "
                          "(static and kinetic alike), as entered in the project; the engineer "
                          "is responsible for its source (the source report's triplet tests, "
                          "Table 1, give values for concrete on masonry).")
               .arg(num(c.slab.mu, 3));
    out << QStringLiteral("The slab falls when its slip across the walls exceeds %1 × d/2 (the "
                          "bearing length); rocking, crushing of the bearing edge and impact are "
                          "not modelled.")
               .arg(num(c.slab.limit, 2));
    if (c.slab.duration)
        out << QStringLiteral("The motion is followed for τ ≤ %1 only (earthquake duration cap).")
                   .arg(num(*c.slab.duration, 1));
    return out;
}

QStringList excitationAssumptions(const Project& p, const ReportAnalysis& a) {
    QStringList out;
    if (hasBasis(a.assessment, CheckBasis::Sine) || hasBasis(a.assessment, CheckBasis::Planar))
        out << QStringLiteral("The floor motion is idealized as an enveloped sine (%1 envelope) at "
                              "the building frequency f = 1/T, with the peak floor acceleration "
                              "A in g; other frequencies enter only through the A_crit(f) curve.")
                   .arg(qs(p.slab.envelope.name()));
    if (p.record)
        out << QStringLiteral(
                   "The record drives the slab %1; the floor motion of the real building "
                   "(higher modes, torsion, nonlinearity) may differ.")
                   .arg(p.record->floor
                            ? QStringLiteral("through a single-mode floor filter "
                                             "(T = %1 s, ζ = %2)")
                                  .arg(num(p.record->floor->period, 3),
                                       num(p.record->floor->damping, 3))
                            : QStringLiteral("directly, as recorded (no floor filter)"));
    if (!a.check.codes.empty())
        out << QStringLiteral("Each code's top-floor force ratio F_top/w_top is read as the peak "
                              "acceleration (in g) of the top floor that the structure must "
                              "resist; the code forces are design forces, reduced by the codes' "
                              "R or q factors, not the elastic response.");
    return out;
}

QStringList modelAssumptions(const Project& p) {
    QStringList out;
    if (p.model != ModelKind::Planar) {
        out << QStringLiteral("The 1-DOF model moves the slab across the walls only: no motion "
                              "along the walls and no vertical motion (the normal force is the "
                              "slab's weight throughout).");
        return out;
    }
    out << QStringLiteral("The planar model moves the slab in both horizontal directions; the "
                          "normal force varies with the vertical floor acceleration.");
    if (p.planar.vertical == VerticalSource::Rsn68Up)
        out << QStringLiteral("The vertical motion is the 1971 San Fernando record at LA "
                              "Hollywood Storage FF, UP component (NGA RSN68): a stand-in for the "
                              "Pacoima Dam vertical of the source report, which is not publicly "
                              "available.");
    if (p.planar.vertical == VerticalSource::None)
        out << QStringLiteral("No vertical motion is applied (gravity only).");
    return out;
}

} // namespace

void addAssumptionsSection(ReportDocument& doc, const Project& p, const ReportAnalysis& a) {
    doc.addSection(QStringLiteral("Assumptions and limitations"));
    QStringList all = slabAssumptions(p);
    all << excitationAssumptions(p, a) << modelAssumptions(p);
    all << QStringLiteral("The check concerns the slab's seating on its walls only; the strength "
                          "of the members, walls and connections is checked elsewhere.");
    for (int k = 0; k < all.size(); ++k)
        doc.addParagraph(QStringLiteral("%1. %2").arg(k + 1).arg(all[k]));
}

} // namespace kinstab::report
