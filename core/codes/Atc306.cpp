// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/codes/Atc306.h"

#include "core/base/NameTable.h"
#include "core/codes/CodeCatalog.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace kinstab {

std::string validateAtc306(const Atc306Inputs& in) {
    std::ostringstream s;
    if (in.mapArea && (*in.mapArea < 1 || *in.mapArea > 7)) {
        s << "atc306.map_area = " << *in.mapArea
          << ": must be between 1 and 7 (ATC 3-06 Table 1-B)";
        return s.str();
    }
    try {
        if (!in.mapArea) {
            requireIn("atc306.aa", in.aa, kAtc306Acceleration, "g");
            requireIn("atc306.av", in.av, kAtc306Acceleration, "g");
        }
        requireIn("atc306.r", in.r, kAtc306R);
    } catch (const InputError& e) {
        return e.what();
    }
    return {};
}

// Table 1-B: map areas 7 … 3 → 0.40 … 0.10; areas 1–2 → 0.05 (docs/codes.md §4.2, L for 1–2).
double atcMapAreaCoefficient(int mapArea) {
    static const double a[] = {0.05, 0.05, 0.05, 0.10, 0.15, 0.20, 0.30, 0.40};
    return a[std::clamp(mapArea, 1, 7)];
}

double atcSoilFactor(AtcSoil s) {
    return s == AtcSoil::S1 ? 1.0 : s == AtcSoil::S2 ? 1.2 : 1.5;
}

// AtcSoil's names, in its declaration order (S1, S2, S3).
constexpr std::array<const char*, 3> kAtcSoilNames = {"S1", "S2", "S3"};
static_assert(kAtcSoilNames.size() == static_cast<std::size_t>(AtcSoil::S3) + 1);

std::string atcSoilName(AtcSoil s) {
    return enumName(kAtcSoilNames, s);
}

std::optional<AtcSoil> atcSoilFromName(const std::string& s) {
    return enumFromName<AtcSoil>(kAtcSoilNames, s);
}

// §4.2.2: T_a = C_T h_n^(3/4) for moment frames (C_T 0.035 steel, 0.025 concrete), else
// T_a = 0.05 h_n / √L, h_n and L in feet.
double atc306FormulaPeriod(const Building& b) {
    if (b.system == StructuralSystem::SteelMomentFrame)
        return 0.035 * std::pow(heightFeet(b), 0.75);
    if (b.system == StructuralSystem::ConcreteMomentFrame)
        return 0.025 * std::pow(heightFeet(b), 0.75);
    return 0.05 * heightFeet(b) / std::sqrt(planDimensionFeet(b));
}

namespace {
void addPeriod(CodeResult& r, const Building& b) {
    const double ta = atc306FormulaPeriod(b);
    if (!b.period) {
        r.periodSeconds = ta;
        r.periodSource = "formula";
        r.trail.push_back({"fundamental period", "T_a", ta, "§4.2.2 eq. 4-3a/4-3b"});
        return;
    }
    // §4.2.2: a period from a substantiated analysis may be used, but not more than 1.2 T_a.
    r.periodSeconds = std::min(*b.period, 1.2 * ta);
    r.periodSource = *b.period > 1.2 * ta ? "entered, capped at 1.2 T_a" : "entered";
    r.trail.push_back({"approximate period", "T_a", ta, "§4.2.2"});
    r.trail.push_back({"fundamental period", "T", r.periodSeconds, "§4.2.2: T <= 1.2 T_a"});
    if (*b.period > 1.2 * ta) r.notes.push_back("entered period capped at 1.2 T_a");
}
} // namespace

CodeResult atc306(const Building& b, const Atc306Inputs& in) {
    CodeResult r = beginCodeResult(b, validateAtc306(in), codeInfo(CodeKey::Atc306));
    addPeriod(r, b);
    const double t = r.periodSeconds;
    const double aa = in.mapArea ? atcMapAreaCoefficient(*in.mapArea) : in.aa;
    const double av = in.mapArea ? atcMapAreaCoefficient(*in.mapArea) : in.av;
    const std::string mapClause =
        in.mapArea ? "Table 1-B, map area " + std::to_string(*in.mapArea) : "§1.4.1 (entered)";
    const double s = atcSoilFactor(in.soil);
    const double csRaw = 1.2 * av * s / (in.r * std::pow(t, 2.0 / 3.0));
    const bool softCap = in.soil == AtcSoil::S3 && aa >= 0.30;
    const double cap = (softCap ? 2.0 : 2.5) * aa / in.r;
    const double cs = std::min(csRaw, cap);
    r.trail.push_back({"effective peak acceleration", "A_a", aa, mapClause});
    r.trail.push_back({"effective peak velocity-related acceleration", "A_v", av, mapClause});
    r.trail.push_back(
        {"soil profile coefficient", "S", s, "Table 3-A, profile " + atcSoilName(in.soil)});
    r.trail.push_back({"response modification factor", "R", in.r, "Table 3-B"});
    r.trail.push_back(
        {"seismic coefficient (eq. 4-2)", "1.2A_vS/(RT^(2/3))", csRaw, "§4.2.1 eq. 4-2"});
    r.trail.push_back({"upper limit", softCap ? "2.0A_a/R" : "2.5A_a/R", cap,
                       softCap ? "§4.2.1 (S3 soil, A_a >= 0.3)" : "§4.2.1 eq. 4-3"});
    r.trail.push_back({"seismic design coefficient", "C_s", cs, "§4.2.1"});
    if (csRaw > cap) r.notes.push_back("C_s capped by the A_a limit");

    const double k = distributionExponent(t);
    r.baseShearCoefficient = cs;
    r.storyForces = distributedRatios(levelWeights(b), levelHeights(b), k, cs);
    r.topRatio = r.storyForces.back();
    const std::vector<double> w = levelWeights(b);
    double total = 0;
    for (double x : w)
        total += x;
    r.trail.push_back({"distribution exponent", "k", k, "§4.3 (1 at T <= 0.5 s, 2 at T >= 2.5 s)"});
    r.trail.push_back({"vertical distribution factor, top", "C_vn",
                       r.topRatio * w.back() / (cs * total), "§4.3 eq. 4-6a"});
    r.trail.push_back({"top ratio", "F_n/w_n", r.topRatio, "§4.3 eq. 4-6"});
    return r;
}

} // namespace kinstab
