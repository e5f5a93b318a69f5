// SPDX-License-Identifier: GPL-3.0-or-later
// The symbols the report uses, with their meaning and unit (Furgerson 1980, ch. IV notation),
// listed once so that tables and figures can use the short forms.
#include "report/ReportSections.h"

namespace kinstab::report {

void addSymbolTable(ReportDocument& doc, const Project& p, const ReportAnalysis& a) {
    doc.addSection(QStringLiteral("Symbols"));
    Table t{{"symbol", "meaning", "unit"},
            {},
            {1.2, 6, 0.8},
            {Align::Left, Align::Left, Align::Left},
            {}};
    t.rows.push_back({"A", "peak floor acceleration of the excitation", "g"});
    t.rows.push_back({"f", "frequency of the floor motion", "Hz"});
    t.rows.push_back(
        {"T", "fundamental period of the building; f = 1/T is the design frequency", "s"});
    t.rows.push_back(
        {"A_crit(f)", "smallest A at frequency f at which the slab slides off its walls", "g"});
    if (!a.codes.empty())
        t.rows.push_back({"F_top/w_top",
                          "a code's lateral force on the top floor per unit weight "
                          "(also F_n/w_n), read as a floor acceleration",
                          "g"});
    t.rows.push_back({"margin", "A_crit / (F_top/w_top); above 1 acceptable", "—"});
    t.rows.push_back({"μ", "coefficient of friction between slab and wall", "—"});
    t.rows.push_back({"d", "wall width (the slab bears on d/2 of it at rest)",
                      lengthSymbolOf(p, LengthScale::Detail)});
    t.rows.push_back({"t*", "characteristic time √(d/2g)", "s"});
    t.rows.push_back({"τ, τc", "time in units of t*; τc: when the slab slides off", "—"});
    t.rows.push_back({"δ", "slip of the slab across the walls in units of d/2", "—"});
    t.rows.push_back(
        {"γc", qs(gammaScaleLabel(p.slab.scale)) + ": collapse factor, 0 where the slab stays on",
         "—"});
    t.rows.push_back({"α, β", "decay and rise rates of the envelope e(t)", "1/s"});
    if (p.model == ModelKind::Planar)
        t.rows.push_back({"f_y, A_y, Θ",
                          "frequency and amplitude along the walls; along-wall "
                          "limit (2 × length / width)",
                          "Hz, g, —"});
    doc.addTable(t);
}

} // namespace kinstab::report
