// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/codes/Ubc1976.h"
#include "core/codes/CodeCatalog.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace kinstab {

std::string validateUbc1976(const Ubc1976Inputs& in) {
    std::ostringstream s;
    if (in.zone < 0 || in.zone > 4) {
        s << "ubc1976.zone = " << in.zone << ": must be 0, 1, 2, 3 or 4 (UBC 1976 Figure 1)";
        return s.str();
    }
    try {
        if (in.importance) requireIn("ubc1976.importance", *in.importance, kUbc1976Importance);
        requireIn("ubc1976.k", in.k, kUbc1976K);
        if (in.sitePeriod)
            requireIn("ubc1976.site_period_s", *in.sitePeriod, kUbc1976SitePeriod, "s");
    } catch (const InputError& e) {
        return e.what();
    }
    return {};
}

// §2312(c): zone 4 added in 1976 with Z = 1; zones 1–3 3/16, 3/8, 3/4. Zone 0 has no
// seismic force requirement (docs/codes.md §2.2).
double ubc1976ZoneFactor(int zone) {
    static const double z[] = {0.0, 3.0 / 16.0, 3.0 / 8.0, 3.0 / 4.0, 1.0};
    return z[std::clamp(zone, 0, 4)];
}

// Table 23-K.
double ubc1976Importance(Occupancy o) {
    switch (o) {
    case Occupancy::Essential:
        return 1.5;
    case Occupancy::Assembly:
        return 1.25;
    default:
        return 1.0;
    }
}

// Eq. 12-3A: T = 0.10 N for a moment frame resisting 100 % of the force; otherwise
// eq. 12-3: T = 0.05 h_n / √D with h_n, D in feet.
double ubc1976FormulaPeriod(const Building& b) {
    if (b.system == StructuralSystem::SteelMomentFrame ||
        b.system == StructuralSystem::ConcreteMomentFrame)
        return 0.10 * b.stories;
    return 0.05 * heightFeet(b) / std::sqrt(planDimensionFeet(b));
}

// §2312(d): S from r = T/T_s, 1.5 when T_s is not established. T ≥ 0.3 s in S, T_s within
// [0.5, 2.5] s, S ≥ 1.0 (docs/codes.md §2.7, §8).
double ubc1976SiteFactor(double period, std::optional<double> sitePeriod) {
    if (!sitePeriod) return 1.5;
    const double r = std::max(period, 0.3) / std::clamp(*sitePeriod, 0.5, 2.5);
    const double s = r <= 1.0 ? 1.0 + r - 0.5 * r * r : 1.2 + 0.6 * r - 0.3 * r * r;
    return std::max(s, 1.0);
}

namespace {
void addPeriod(CodeResult& r, const Building& b) {
    if (b.period) {
        r.periodSeconds = *b.period;
        r.periodSource = "entered";
        r.trail.push_back({"fundamental period (entered)", "T", r.periodSeconds, "§2312(b)"});
        return;
    }
    r.periodSeconds = ubc1976FormulaPeriod(b);
    const bool frame = b.system == StructuralSystem::SteelMomentFrame ||
                       b.system == StructuralSystem::ConcreteMomentFrame;
    r.periodSource = frame ? "formula 0.10 N" : "formula 0.05 h_n/sqrt(D)";
    if (!frame) {
        r.trail.push_back({"height", "h_n", heightFeet(b), "ft"});
        r.trail.push_back({"plan dimension", "D", planDimensionFeet(b), "ft"});
    }
    r.trail.push_back({"fundamental period", "T", r.periodSeconds,
                       frame ? "§2312(b) eq. 12-3A" : "§2312(b) eq. 12-3"});
}
} // namespace

CodeResult ubc1976(const Building& b, const Ubc1976Inputs& in) {
    CodeResult r = beginCodeResult(b, validateUbc1976(in), codeInfo(CodeKey::Ubc1976));
    addPeriod(r, b);
    const double t = r.periodSeconds;
    const double z = ubc1976ZoneFactor(in.zone);
    const double i = in.importance.value_or(ubc1976Importance(b.occupancy));
    const double cRaw = 1.0 / (15.0 * std::sqrt(t));
    const double c = std::min(cRaw, 0.12);
    const double s = ubc1976SiteFactor(t, in.sitePeriod);
    const double cs = std::min(c * s, 0.14);
    const double v = z * i * in.k * cs;
    r.trail.push_back({"zone coefficient", "Z", z, "§2312(c), zone " + std::to_string(in.zone)});
    r.trail.push_back(
        {"importance factor", "I", i, in.importance ? "Table 23-K (entered)" : "Table 23-K"});
    r.trail.push_back({"horizontal force factor", "K", in.k, "Table 23-I"});
    r.trail.push_back(
        {"period coefficient", "C", c, "§2312(d) eq. 12-2, C = 1/(15 sqrt(T)) <= 0.12"});
    if (in.sitePeriod) r.trail.push_back({"site period", "T_s", *in.sitePeriod, "§2312(d)"});
    r.trail.push_back(
        {"site-structure resonance coefficient", "S", s,
         in.sitePeriod ? "§2312(d) eq. 12-4" : "§2312(d): T_s not established, S = 1.5"});
    r.trail.push_back({"product", "CS", cs, "§2312(d): CS need not exceed 0.14"});
    r.trail.push_back({"base shear coefficient", "V/W", v, "§2312(d) eq. 12-1, V = ZIKCSW"});
    if (cRaw > 0.12) r.notes.push_back("C capped at 0.12");
    if (c * s > 0.14) r.notes.push_back("CS capped at 0.14");
    if (in.zone == 0) r.notes.push_back("zone 0: no seismic force requirement");

    // §2312(e) eq. 12-6: F_t = 0.07 T V <= 0.25 V, 0 for T <= 0.7 s.
    const double ft = t <= 0.7 ? 0.0 : std::min(0.07 * t, 0.25) * v;
    r.trail.push_back(
        {"top force", "F_t/W", ft, "§2312(e) eq. 12-6, F_t = 0.07TV <= 0.25V, 0 for T <= 0.7 s"});
    const TopForceDistribution d = distributeWithTopForce(b, v, ft);
    r.storyForces = d.ratios;
    r.topRatioWithoutFt = d.topWithoutFt;
    r.baseShearCoefficient = v;
    r.topRatio = r.storyForces.back();
    r.trail.push_back({"top ratio without F_t (the paper's figure)", "F_n/w_n",
                       *r.topRatioWithoutFt, "§2312(e) eq. 12-7"});
    r.trail.push_back(
        {"top ratio with F_t", "(F_n+F_t)/w_n", r.topRatio, "§2312(e) eqs. 12-6, 12-7"});
    return r;
}

} // namespace kinstab
