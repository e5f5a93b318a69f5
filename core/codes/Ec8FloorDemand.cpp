// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/codes/Ec8FloorDemand.h"

#include <algorithm>

namespace kinstab {

double ec8FloorFactor(double zOverH, double ta, double t1) {
    const double detune = 1.0 - ta / t1;
    return std::max(3.0 * (1.0 + zOverH) / (1.0 + detune * detune) - 0.5, 1.0);
}

FloorDemand ec8FloorDemand(const Building& b, const Eurocode8Inputs& in,
                           std::optional<double> elementPeriod, int slabLevel) {
    beginCodeResult(b, validateEurocode8(in), codeInfo(CodeKey::Ec8)); // validates only
    requireRange("floors.slab_level", slabLevel, 1, b.stories);
    if (elementPeriod) requireRange("floors.ec8_element_period_s", *elementPeriod, 0.0, 100.0, "s");
    FloorDemand d;
    d.code = "ec8";
    d.title = "EN 1998-1:2004 §4.3.5.2";
    d.slabLevel = slabLevel;
    const double t1 = b.period.value_or(eurocode8FormulaPeriod(b));
    const double ta = elementPeriod.value_or(0.0);
    const Ec8SpectrumParameters p = ec8Spectrum(in.ground, in.spectrumType);
    const int cls = in.importanceClass.value_or(ec8ImportanceClass(b.occupancy));
    const double gammaI = in.gammaI.value_or(ec8ImportanceFactor(cls));
    const double alpha = gammaI * in.agr;
    d.zOverH = relativeLevelHeights(b);
    for (double z : d.zOverH) {
        d.factor.push_back(ec8FloorFactor(z, ta, t1));
        d.pfa.push_back(alpha * p.s * d.factor.back());
    }
    const auto at = static_cast<std::size_t>(slabLevel - 1);
    d.slabPfa = d.pfa[at];
    d.groundPga = alpha * p.s;
    d.groundPgaSource = "alpha S";
    d.trail = {
        {"reference peak ground acceleration", "a_gR", in.agr, "§3.2.1 (entered)"},
        {"importance factor", "gamma_I", gammaI, in.gammaI ? "§4.2.5 (entered)" : "§4.2.5(5)P"},
        {"design ground acceleration ratio", "alpha", alpha, "§4.3.5.2(3): a_g/g"},
        {"soil factor", "S", p.s, "Table 3.2/3.3, ground type " + ec8GroundName(in.ground)},
        {"building's fundamental period", "T_1", t1,
         b.period ? "entered" : "§4.3.3.2.2(3) eq. 4.6"},
        {"element's fundamental period", "T_a", ta, elementPeriod ? "entered" : "rigid element"},
        {"relative height of the slab's level", "z/H", d.zOverH[at], "§4.3.5.2(3)"},
        {"amplification", "S_a/(alpha S)", d.factor[at], "eq. 4.25"},
        {"seismic coefficient", "S_a", d.slabPfa, "§4.3.5.2(3) eq. 4.25, gamma_a = q_a = 1"},
    };
    return d;
}

} // namespace kinstab
