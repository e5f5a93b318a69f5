// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/codes/Building.h"

#include "core/base/NameTable.h"

#include "core/codes/CodeResult.h"

#include <cmath>
#include <numeric>
#include <sstream>

namespace kinstab {

namespace {

constexpr double kFoot = 0.3048; // m, exact

std::string checkVector(const std::string& field, const std::vector<double>& v, int stories) {
    if (v.empty()) return {};
    std::ostringstream s;
    if (static_cast<int>(v.size()) != stories) {
        s << field << " has " << v.size() << " entries: must have one per story (" << stories
          << ")";
        return s.str();
    }
    for (std::size_t i = 0; i < v.size(); ++i)
        if (!std::isfinite(v[i]) || v[i] <= 0.0 || v[i] > 1e12) {
            s << field << "[" << i << "] = " << v[i] << ": must be > 0 and at most 1e12";
            return s.str();
        }
    return {};
}

} // namespace

std::string validateBuilding(const Building& b) {
    std::ostringstream s;
    if (b.stories < 1 || b.stories > kMaxStories) {
        s << "building.stories = " << b.stories << ": must be between 1 and " << kMaxStories;
        return s.str();
    }
    try {
        requireAbove("building.height", b.height, 0.0, maxBuildingHeight(b.unit), unitName(b.unit));
        requireAbove("building.plan_dimension", b.planDimension, 0.0, maxPlanDimension(b.unit),
                     unitName(b.unit));
        if (b.period) requireRange("building.period_s", *b.period, kMinPeriodS, kMaxPeriodS, "s");
    } catch (const InputError& e) {
        return e.what();
    }
    std::string e = checkVector("building.story_weights", b.storyWeights, b.stories);
    if (e.empty()) e = checkVector("building.story_heights", b.storyHeights, b.stories);
    if (!e.empty()) return e;
    if (!b.storyHeights.empty()) {
        const double sum = std::accumulate(b.storyHeights.begin(), b.storyHeights.end(), 0.0);
        if (std::abs(sum - b.height) > 1e-6 * b.height) {
            s << "building.story_heights sum to " << sum << " " << unitName(b.unit)
              << ": must equal building.height = " << b.height;
            return s.str();
        }
    }
    return {};
}

void requireValidBuilding(const Building& b) {
    const std::string e = validateBuilding(b);
    if (!e.empty()) throw InputError(e);
}

double maxBuildingHeight(LengthUnit u) {
    return u == LengthUnit::Feet ? 3000.0 : 1000.0;
}
double maxPlanDimension(LengthUnit u) {
    return u == LengthUnit::Feet ? 10000.0 : 3000.0;
}

double metresPerUnit(LengthUnit u) {
    return u == LengthUnit::Feet ? kFoot : 1.0;
}
double heightMetres(const Building& b) {
    return b.height * metresPerUnit(b.unit);
}
double heightFeet(const Building& b) {
    return heightMetres(b) / kFoot;
}
double planDimensionMetres(const Building& b) {
    return b.planDimension * metresPerUnit(b.unit);
}
double planDimensionFeet(const Building& b) {
    return planDimensionMetres(b) / kFoot;
}

std::vector<double> levelWeights(const Building& b) {
    if (!b.storyWeights.empty()) return b.storyWeights;
    return std::vector<double>(static_cast<std::size_t>(b.stories), 1.0);
}

std::vector<double> levelHeights(const Building& b) {
    std::vector<double> h(static_cast<std::size_t>(b.stories));
    double z = 0;
    for (std::size_t i = 0; i < h.size(); ++i) {
        // Uniform stories: h_i = i h_n / n exactly (no accumulated rounding at the roof).
        z = b.storyHeights.empty() ? b.height * static_cast<double>(i + 1) / b.stories
                                   : z + b.storyHeights[i];
        h[i] = z;
    }
    return h;
}

int occupancyClass(Occupancy o) {
    switch (o) {
    case Occupancy::Essential:
        return 4;
    case Occupancy::Assembly:
    case Occupancy::Hazardous:
        return 3;
    default:
        return 2;
    }
}

// LengthUnit's names, in its declaration order (Feet, Metres).
constexpr std::array<const char*, 2> kLengthUnitNames = {"ft", "m"};
static_assert(kLengthUnitNames.size() == static_cast<std::size_t>(LengthUnit::Metres) + 1);

std::string unitName(LengthUnit u) {
    return enumName(kLengthUnitNames, u);
}

std::optional<LengthUnit> unitFromName(const std::string& s) {
    return enumFromName<LengthUnit>(kLengthUnitNames, s);
}

namespace {
const std::vector<std::pair<StructuralSystem, std::string>>& systemTable() {
    static const std::vector<std::pair<StructuralSystem, std::string>> t = {
        {StructuralSystem::SteelMomentFrame, "steel_moment_frame"},
        {StructuralSystem::ConcreteMomentFrame, "concrete_moment_frame"},
        {StructuralSystem::SteelBracedEccentric, "steel_eccentric_braced"},
        {StructuralSystem::DualFrameWall, "dual_frame_wall"},
        {StructuralSystem::ShearWall, "shear_wall"},
        {StructuralSystem::BracedFrame, "braced_frame"},
        {StructuralSystem::Other, "other"},
    };
    return t;
}
const std::vector<std::pair<Occupancy, std::string>>& occupancyTable() {
    static const std::vector<std::pair<Occupancy, std::string>> t = {
        {Occupancy::Standard, "standard"},
        {Occupancy::Assembly, "assembly"},
        {Occupancy::Hazardous, "hazardous"},
        {Occupancy::Essential, "essential"},
    };
    return t;
}
} // namespace

std::string systemName(StructuralSystem s) {
    for (const auto& [k, n] : systemTable())
        if (k == s) return n;
    return "other";
}

std::optional<StructuralSystem> systemFromName(const std::string& s) {
    for (const auto& [k, n] : systemTable())
        if (n == s) return k;
    return std::nullopt;
}

std::vector<std::string> systemNames() {
    std::vector<std::string> v;
    for (const auto& e : systemTable())
        v.push_back(e.second);
    return v;
}

std::string occupancyName(Occupancy o) {
    for (const auto& [k, n] : occupancyTable())
        if (k == o) return n;
    return "standard";
}

std::optional<Occupancy> occupancyFromName(const std::string& s) {
    for (const auto& [k, n] : occupancyTable())
        if (n == s) return k;
    return std::nullopt;
}

std::vector<std::string> occupancyNames() {
    std::vector<std::string> v;
    for (const auto& e : occupancyTable())
        v.push_back(e.second);
    return v;
}

} // namespace kinstab
