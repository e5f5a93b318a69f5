// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/codes/Asce7FloorDemand.h"

#include <algorithm>
#include <cmath>

namespace kinstab {

double asce7HeightFactor(double zOverH, double ta) {
    const double a1 = std::min(1.0 / ta, 2.5);
    const double a2 = std::max(1.0 - (0.4 / ta) * (0.4 / ta), 0.0);
    return 1.0 + a1 * zOverH + a2 * std::pow(zOverH, 10.0);
}

double asce7DuctilityFactor(double r, double importance, double omega0) {
    return std::max(std::sqrt(1.1 * r / (importance * omega0)), 1.3);
}

FloorDemand asce7FloorDemand(const Building& b, const Asce7Inputs& in, double omega0, int slabLevel,
                             bool mce) {
    beginCodeResult(b, validateAsce7(in), codeInfo(CodeKey::Asce7_22)); // validates only
    requireRange("floors.asce7_omega0", omega0, 1.0, 5.0);
    requireRange("floors.slab_level", slabLevel, 1, b.stories);
    FloorDemand d;
    d.code = mce ? "asce7_22_mce" : "asce7_22";
    d.title = mce ? "ASCE/SEI 7-22 §13.3.1, MCE_R level" : "ASCE/SEI 7-22 §13.3.1, design level";
    d.slabLevel = slabLevel;
    const double ta = asce7ApproximatePeriod(b);
    const int rc = in.riskCategory.value_or(asceRiskCategory(b.occupancy));
    const double ie = in.importance.value_or(asceImportance(rc));
    const double rmu = asce7DuctilityFactor(in.r, ie, omega0);
    const double s = mce ? 1.5 * in.sds : in.sds;
    d.zOverH = relativeLevelHeights(b);
    for (double z : d.zOverH) {
        d.factor.push_back(asce7HeightFactor(z, ta));
        d.pfa.push_back(0.4 * s * d.factor.back() / rmu);
    }
    const auto at = static_cast<std::size_t>(slabLevel - 1);
    d.slabPfa = d.pfa[at];
    d.groundPga = 0.4 * s;
    d.groundPgaSource = mce ? "0.4 S_MS" : "0.4 S_DS";
    d.trail = {
        {"approximate period", "T_a", ta, "§12.8.2.1 eq. 12.8-7, Table 12.8-2"},
        {"height coefficient", "a_1", std::min(1.0 / ta, 2.5), "eq. 13.3-4: 1/T_a <= 2.5"},
        {"height coefficient", "a_2", std::max(1.0 - (0.4 / ta) * (0.4 / ta), 0.0),
         "eq. 13.3-4: 1 - (0.4/T_a)^2 >= 0"},
        {"relative height of the slab's level", "z/h", d.zOverH[at], "§13.3.1"},
        {"height factor", "H_f", d.factor[at], "§13.3.1 eq. 13.3-4"},
        {"response modification coefficient", "R", in.r, "Table 12.2-1"},
        {"importance factor", "I_e", ie, "Table 1.5-2"},
        {"overstrength factor", "Omega_0", omega0, "Table 12.2-1 (entered)"},
        {"structure ductility reduction factor", "R_mu", rmu, "§13.3.1 eq. 13.3-6"},
        {mce ? "MCE_R spectral acceleration, short" : "design spectral acceleration, short",
         mce ? "S_MS" : "S_DS", s, mce ? "§11.4.5: S_DS = 2/3 S_MS" : "§11.4.5 (entered)"},
        {"peak floor acceleration", "PFA/g", d.slabPfa,
         mce ? "0.4 S_MS H_f / R_mu" : "eq. 13.3-1 with I_p = C_AR = R_po = 1"},
    };
    if (!mce) {
        const double fp = std::clamp(d.slabPfa, 0.3 * in.sds, 1.6 * in.sds);
        d.trail.push_back(
            {"component force ratio, rigid, I_p = 1", "F_p/W_p", fp, "eqs. 13.3-1 to 13.3-3"});
        if (fp != d.slabPfa)
            d.notes.push_back("the F_p bound of eq. 13.3-2/13.3-3 governs the force, not the PFA");
    }
    d.notes.push_back("T_a from §12.8.2.1 (eq. 12.8-7), not the entered period, as §13.3.1 asks");
    return d;
}

} // namespace kinstab
