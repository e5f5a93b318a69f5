// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/codes/Ubc1997.h"
#include "core/codes/CodeCatalog.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace kinstab {

namespace {
constexpr int zoneIndex(Ubc97Zone z) {
    return static_cast<int>(z);
}
const char* const kZoneNames[] = {"1", "2A", "2B", "3", "4"};
const char* const kSoilNames[] = {"SA", "SB", "SC", "SD", "SE"};
} // namespace

std::string validateUbc1997(const Ubc1997Inputs& in) {
    try {
        requireIn("ubc1997.na", in.na, kUbc1997Na);
        requireIn("ubc1997.nv", in.nv, kUbc1997Nv);
        if (in.importance) requireIn("ubc1997.importance", *in.importance, kUbc1997Importance);
        requireIn("ubc1997.r", in.r, kUbc1997R);
    } catch (const InputError& e) {
        return e.what();
    }
    if (in.zone != Ubc97Zone::Z4 && (in.na != 1.0 || in.nv != 1.0)) {
        std::ostringstream s;
        s << "ubc1997.na/nv = " << in.na << "/" << in.nv
          << ": near-source factors apply in zone 4 only (must be 1)";
        return s.str();
    }
    return {};
}

// Table 16-I.
double ubc97ZoneFactor(Ubc97Zone z) {
    static const double f[] = {0.075, 0.15, 0.20, 0.30, 0.40};
    return f[zoneIndex(z)];
}

std::string ubc97ZoneName(Ubc97Zone z) {
    return kZoneNames[zoneIndex(z)];
}

std::optional<Ubc97Zone> ubc97ZoneFromName(const std::string& s) {
    for (int i = 0; i < 5; ++i)
        if (s == kZoneNames[i]) return static_cast<Ubc97Zone>(i);
    return std::nullopt;
}

std::string ubc97SoilName(Ubc97Soil s) {
    return kSoilNames[static_cast<int>(s)];
}

std::optional<Ubc97Soil> ubc97SoilFromName(const std::string& s) {
    for (int i = 0; i < 5; ++i)
        if (s == kSoilNames[i]) return static_cast<Ubc97Soil>(i);
    return std::nullopt;
}

// Tables 16-Q and 16-R (rows S_A … S_E, columns Z = 0.075 … 0.4); the zone-4 column is
// multiplied by the near-source factor.
double ubc97Ca(Ubc97Soil s, Ubc97Zone z, double na) {
    static const double t[5][5] = {{0.06, 0.12, 0.16, 0.24, 0.32},
                                   {0.08, 0.15, 0.20, 0.30, 0.40},
                                   {0.09, 0.18, 0.24, 0.33, 0.40},
                                   {0.12, 0.22, 0.28, 0.36, 0.44},
                                   {0.19, 0.30, 0.34, 0.36, 0.36}};
    const double c = t[static_cast<int>(s)][zoneIndex(z)];
    return z == Ubc97Zone::Z4 ? c * na : c;
}

double ubc97Cv(Ubc97Soil s, Ubc97Zone z, double nv) {
    static const double t[5][5] = {{0.06, 0.12, 0.16, 0.24, 0.32},
                                   {0.08, 0.15, 0.20, 0.30, 0.40},
                                   {0.13, 0.25, 0.32, 0.45, 0.56},
                                   {0.18, 0.32, 0.40, 0.54, 0.64},
                                   {0.26, 0.50, 0.64, 0.84, 0.96}};
    const double c = t[static_cast<int>(s)][zoneIndex(z)];
    return z == Ubc97Zone::Z4 ? c * nv : c;
}

// Table 16-K: essential and hazardous facilities 1.25, all others 1.00.
double ubc1997Importance(Occupancy o) {
    return o == Occupancy::Essential || o == Occupancy::Hazardous ? 1.25 : 1.0;
}

// §1630.2.2 Method A, eq. 30-8: T = C_t h_n^(3/4), h_n in feet; C_t 0.035 steel moment frames,
// 0.030 concrete moment frames and eccentrically braced frames, 0.020 all others.
double ubc1997FormulaPeriod(const Building& b) {
    double ct = 0.020;
    if (b.system == StructuralSystem::SteelMomentFrame)
        ct = 0.035;
    else if (b.system == StructuralSystem::ConcreteMomentFrame ||
             b.system == StructuralSystem::SteelBracedEccentric)
        ct = 0.030;
    return ct * std::pow(heightFeet(b), 0.75);
}

namespace {
void addPeriod(CodeResult& r, const Building& b, Ubc97Zone zone) {
    const double ta = ubc1997FormulaPeriod(b);
    if (!b.period) {
        r.periodSeconds = ta;
        r.periodSource = "formula";
        r.trail.push_back({"fundamental period (Method A)", "T", ta, "§1630.2.2 eq. 30-8"});
        return;
    }
    // §1630.2.2 Method B: not more than 30 % above Method A in zone 4, 40 % in zones 1–3.
    const double cap = (zone == Ubc97Zone::Z4 ? 1.3 : 1.4) * ta;
    r.periodSeconds = std::min(*b.period, cap);
    r.periodSource = *b.period > cap ? "entered, capped (Method B limit)" : "entered";
    r.trail.push_back({"Method A period", "T_A", ta, "§1630.2.2 eq. 30-8"});
    r.trail.push_back({"fundamental period", "T", r.periodSeconds, "§1630.2.2 Method B limit"});
    if (*b.period > cap) r.notes.push_back("entered period capped at the Method B limit");
}
} // namespace

CodeResult ubc1997(const Building& b, const Ubc1997Inputs& in) {
    CodeResult r = beginCodeResult(b, validateUbc1997(in), codeInfo(CodeKey::Ubc1997));
    addPeriod(r, b, in.zone);
    const double t = r.periodSeconds;
    const double z = ubc97ZoneFactor(in.zone);
    const double i = in.importance.value_or(ubc1997Importance(b.occupancy));
    const double ca = ubc97Ca(in.soil, in.zone, in.na), cv = ubc97Cv(in.soil, in.zone, in.nv);
    const double main = cv * i / (in.r * t);  // eq. 30-4
    const double upper = 2.5 * ca * i / in.r; // eq. 30-5
    const double lower = 0.11 * ca * i;       // eq. 30-6
    const bool zone4 = in.zone == Ubc97Zone::Z4;
    const double lower4 = zone4 ? 0.8 * z * in.nv * i / in.r : 0.0; // eq. 30-7
    const double v = std::max({std::min(main, upper), lower, lower4});
    r.trail.push_back({"zone factor", "Z", z, "Table 16-I, zone " + ubc97ZoneName(in.zone)});
    r.trail.push_back({"seismic coefficient", "C_a", ca, "Table 16-Q, " + ubc97SoilName(in.soil)});
    r.trail.push_back({"seismic coefficient", "C_v", cv, "Table 16-R, " + ubc97SoilName(in.soil)});
    if (zone4) {
        r.trail.push_back({"near-source factor", "N_a", in.na, "Table 16-S"});
        r.trail.push_back({"near-source factor", "N_v", in.nv, "Table 16-T"});
    }
    r.trail.push_back(
        {"importance factor", "I", i, in.importance ? "Table 16-K (entered)" : "Table 16-K"});
    r.trail.push_back({"response modification factor", "R", in.r, "Table 16-N"});
    r.trail.push_back({"base shear", "C_vI/(RT)", main, "§1630.2.1 eq. 30-4"});
    r.trail.push_back({"upper limit", "2.5C_aI/R", upper, "eq. 30-5"});
    r.trail.push_back({"lower limit", "0.11C_aI", lower, "eq. 30-6"});
    if (zone4) r.trail.push_back({"zone-4 lower limit", "0.8ZN_vI/R", lower4, "eq. 30-7"});
    r.trail.push_back({"base shear coefficient", "V/W", v, "§1630.2.1"});
    if (main > upper) r.notes.push_back("eq. 30-5 upper limit governs");
    if (std::min(main, upper) < std::max(lower, lower4)) r.notes.push_back("a lower limit governs");

    const double ft = t <= 0.7 ? 0.0 : std::min(0.07 * t, 0.25) * v; // eq. 30-14
    r.trail.push_back({"top force", "F_t/W", ft, "§1630.5 eq. 30-14"});
    const TopForceDistribution d = distributeWithTopForce(b, v, ft);
    r.storyForces = d.ratios;
    r.topRatioWithoutFt = d.topWithoutFt;
    r.baseShearCoefficient = v;
    r.topRatio = r.storyForces.back();
    r.trail.push_back({"top ratio with F_t", "(F_n+F_t)/w_n", r.topRatio, "§1630.5 eq. 30-15"});
    return r;
}

} // namespace kinstab
