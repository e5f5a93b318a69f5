// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/codes/Asce7_22.h"
#include "core/codes/CodeCatalog.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace kinstab {

std::vector<std::string> asceSiteClassNames() {
    return {"A", "B", "BC", "C", "CD", "D", "DE", "E", "F", "Default"};
}

std::string validateAsce7(const Asce7Inputs& in) {
    try {
        requireIn("asce7_22.sds", in.sds, kAsce7Sd, "g");
        requireIn("asce7_22.sd1", in.sd1, kAsce7Sd, "g");
        if (in.s1) requireIn("asce7_22.s1", *in.s1, kAsce7S1, "g");
        requireIn("asce7_22.tl", in.tl, kAsce7Tl, "s");
        if (in.importance) requireIn("asce7_22.importance", *in.importance, kAsce7Importance);
        requireIn("asce7_22.r", in.r, kAsce7R);
    } catch (const InputError& e) {
        return e.what();
    }
    std::ostringstream s;
    if (in.riskCategory && (*in.riskCategory < 1 || *in.riskCategory > 4)) {
        s << "asce7_22.risk_category = " << *in.riskCategory << ": must be 1, 2, 3 or 4 (I–IV)";
        return s.str();
    }
    const auto names = asceSiteClassNames();
    if (std::find(names.begin(), names.end(), in.siteClass) == names.end())
        return "asce7_22.site_class = '" + in.siteClass +
               "': must be one of A B BC C CD D DE E F Default";
    if (in.siteClass == "F")
        return "asce7_22.site_class = 'F': needs a site response analysis (§20.2.1), not the ELF";
    return {};
}

// Table 1.5-1 (mapping of occupancy, docs/codes.md §5.5).
int asceRiskCategory(Occupancy o) {
    return occupancyClass(o);
}

// Table 1.5-2: I, II → 1.00; III → 1.25; IV → 1.50.
double asceImportance(int rc) {
    return rc <= 2 ? 1.0 : rc == 3 ? 1.25 : 1.5;
}

// Table 12.8-1: C_u 1.4 (S_D1 ≥ 0.4), 1.4 (0.3), 1.5 (0.2), 1.6 (0.15), 1.7 (≤ 0.1), interpolated.
double asceUpperLimitCoefficient(double sd1) {
    static const double x[] = {0.1, 0.15, 0.2, 0.3, 0.4};
    static const double y[] = {1.7, 1.6, 1.5, 1.4, 1.4};
    if (sd1 <= x[0]) return y[0];
    for (int i = 1; i < 5; ++i)
        if (sd1 <= x[i]) return y[i - 1] + (y[i] - y[i - 1]) * (sd1 - x[i - 1]) / (x[i] - x[i - 1]);
    return y[4];
}

// Table 12.8-2, h_n in feet: steel moment frames 0.028 h^0.8, concrete moment frames
// 0.016 h^0.9, steel EBF/BRBF 0.03 h^0.75, all other systems 0.02 h^0.75.
double asce7ApproximatePeriod(const Building& b) {
    const double h = heightFeet(b);
    switch (b.system) {
    case StructuralSystem::SteelMomentFrame:
        return 0.028 * std::pow(h, 0.8);
    case StructuralSystem::ConcreteMomentFrame:
        return 0.016 * std::pow(h, 0.9);
    case StructuralSystem::SteelBracedEccentric:
        return 0.03 * std::pow(h, 0.75);
    default:
        return 0.02 * std::pow(h, 0.75);
    }
}

namespace {
void addPeriod(CodeResult& r, const Building& b, double sd1) {
    const double ta = asce7ApproximatePeriod(b);
    r.trail.push_back({"approximate period", "T_a", ta, "§12.8.2.1 eq. 12.8-7, Table 12.8-2"});
    if (!b.period) {
        r.periodSeconds = ta;
        r.periodSource = "formula";
        return;
    }
    // §12.8.2: the period used may not exceed C_u T_a (docs/codes.md §8).
    const double cu = asceUpperLimitCoefficient(sd1);
    r.periodSeconds = std::min(*b.period, cu * ta);
    r.periodSource = *b.period > cu * ta ? "entered, capped at C_u T_a" : "entered";
    r.trail.push_back({"upper-limit coefficient", "C_u", cu, "Table 12.8-1"});
    r.trail.push_back({"fundamental period", "T", r.periodSeconds, "§12.8.2: T <= C_u T_a"});
    if (*b.period > cu * ta) r.notes.push_back("entered period capped at C_u T_a");
}
} // namespace

CodeResult asce7_22(const Building& b, const Asce7Inputs& in) {
    CodeResult r = beginCodeResult(b, validateAsce7(in), codeInfo(CodeKey::Asce7_22));
    addPeriod(r, b, in.sd1);
    const double t = r.periodSeconds;
    const int rc = in.riskCategory.value_or(asceRiskCategory(b.occupancy));
    const double ie = in.importance.value_or(asceImportance(rc));
    const double rie = in.r / ie;
    const double eq2 = in.sds / rie; // eq. 12.8-2
    const bool longPeriod = t > in.tl;
    const double eq3 = longPeriod ? in.sd1 * in.tl / (t * t * rie) : in.sd1 / (t * rie); // 12.8-3/4
    const double eq5 = std::max(0.044 * in.sds * ie, 0.01); // eq. 12.8-5
    const bool nearFault = in.s1 && *in.s1 >= 0.6;
    const double eq6 = nearFault ? 0.5 * *in.s1 / rie : 0.0; // eq. 12.8-6
    // Minimum of the spectrum branches first, then the floors (docs/codes.md §8).
    const double cs = std::max({std::min(eq2, eq3), eq5, eq6});
    r.trail.push_back({"design spectral acceleration, short", "S_DS", in.sds,
                       "§11.4.5 (entered, site class " + in.siteClass + ")"});
    r.trail.push_back({"design spectral acceleration, 1 s", "S_D1", in.sd1, "§11.4.5 (entered)"});
    r.trail.push_back({"long-period transition period", "T_L", in.tl, "§11.4.6 (entered)"});
    r.trail.push_back({"risk category", "RC", static_cast<double>(rc), "Table 1.5-1"});
    r.trail.push_back(
        {"importance factor", "I_e", ie, in.importance ? "Table 1.5-2 (entered)" : "Table 1.5-2"});
    r.trail.push_back({"response modification coefficient", "R", in.r, "Table 12.2-1"});
    r.trail.push_back({"spectral limit", "S_DS/(R/I_e)", eq2, "eq. 12.8-2"});
    r.trail.push_back({"period limit", longPeriod ? "S_D1T_L/(T^2R/I_e)" : "S_D1/(TR/I_e)", eq3,
                       longPeriod ? "eq. 12.8-4" : "eq. 12.8-3"});
    r.trail.push_back({"minimum", "0.044S_DSI_e >= 0.01", eq5, "eq. 12.8-5"});
    if (nearFault)
        r.trail.push_back({"minimum where S_1 >= 0.6", "0.5S_1/(R/I_e)", eq6, "eq. 12.8-6"});
    r.trail.push_back({"seismic response coefficient", "C_s", cs, "§12.8.1.1"});
    if (cs > std::min(eq2, eq3)) r.notes.push_back("a C_s floor (eq. 12.8-5/6) governs");
    r.notes.push_back("§11.4.8 site-specific requirements and exceptions are not applied");

    const double k = distributionExponent(t);
    r.baseShearCoefficient = cs;
    r.storyForces = distributedRatios(levelWeights(b), levelHeights(b), k, cs);
    r.topRatio = r.storyForces.back();
    r.trail.push_back({"distribution exponent", "k", k, "§12.8.3"});
    r.trail.push_back({"top ratio", "F_n/w_n", r.topRatio, "§12.8.3 eqs. 12.8-11, 12.8-12"});
    return r;
}

} // namespace kinstab
