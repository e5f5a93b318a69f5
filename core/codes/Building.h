// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The building an engineer describes once for every code (docs/theory.md §9, docs/codes.md §0):
// stories with their weights and heights (uniform by default), total height h_n, plan dimension D
// parallel to the force, period entered or left to each code's own formula, units, system,
// occupancy.

#include "core/base/InputError.h"

#include <optional>
#include <string>
#include <vector>

namespace kinstab {

enum class LengthUnit { Feet, Metres };

// Lateral system, as far as the codes' period formulas and tables need it.
enum class StructuralSystem {
    SteelMomentFrame,     // moment frame resisting 100 % of the force, steel
    ConcreteMomentFrame,  // moment frame resisting 100 % of the force, reinforced concrete
    SteelBracedEccentric, // steel eccentrically (or buckling-restrained) braced frame
    DualFrameWall,        // moment frame + shear walls (the paper's building)
    ShearWall,            // concrete or masonry shear walls (bearing-wall or building-frame)
    BracedFrame,          // concentrically braced frame
    Other,
};

// What the building is used for; each code maps it to its own importance factor unless the
// code's inputs give one explicitly.
enum class Occupancy {
    Standard,  // offices, dwellings, commerce (the paper's building)
    Assembly,  // large assembly (> 300 persons in one room)
    Hazardous, // hazardous contents
    Essential, // hospitals, fire and police stations, emergency centres
};

struct Building {
    std::string name;
    int stories = 16;
    LengthUnit unit = LengthUnit::Feet;
    double height = 177.0;        // h_n, roof above the base, in `unit`
    double planDimension = 78.62; // D (UBC) / L (ATC): plan dimension parallel to the force
    std::optional<double> period; // s; nullopt: each code estimates it with its own formula
    StructuralSystem system = StructuralSystem::DualFrameWall;
    Occupancy occupancy = Occupancy::Standard;
    std::vector<double> storyWeights; // bottom first, any unit of weight; empty: all equal
    std::vector<double> storyHeights; // bottom first, in `unit`, summing to height; empty: equal
};

// Limits validateBuilding enforces, read also by the building panel. 300 stories and 3000 ft
// (1000 m) are well beyond the tallest building; a plan of 10,000 ft (3000 m) is no building;
// a fundamental period of 20 s is beyond any code's spectrum. The stiffest buildings (one-storey
// masonry boxes) have periods of about 0.05 s; 0.02 s leaves a factor 2.5 below them, and the
// slab's check runs its sine at 1 / T, so a shorter period only multiplies its work.
inline constexpr int kMaxStories = 300;
inline constexpr double kMinPeriodS = 0.02;
inline constexpr double kMaxPeriodS = 20.0;
double maxBuildingHeight(LengthUnit u); // in u
double maxPlanDimension(LengthUnit u);  // in u

std::string validateBuilding(const Building& b); // empty when fine
void requireValidBuilding(const Building& b);    // throws InputError

double metresPerUnit(LengthUnit u);
double heightFeet(const Building& b);
double heightMetres(const Building& b);
double planDimensionFeet(const Building& b);
double planDimensionMetres(const Building& b);

// Per level, bottom first (level n = roof last): weights and heights above the base in `unit`.
std::vector<double> levelWeights(const Building& b);
std::vector<double> levelHeights(const Building& b);

// The four-class scale shared by ASCE 7 risk categories (Table 1.5-1) and EN 1998-1 importance
// classes (Table 4.3): ordinary II, assembly or hazardous contents III, essential IV.
int occupancyClass(Occupancy o);

std::string unitName(LengthUnit u); // "ft" | "m"
std::optional<LengthUnit> unitFromName(const std::string& s);
std::string systemName(StructuralSystem s); // e.g. "dual_frame_wall"
std::optional<StructuralSystem> systemFromName(const std::string& s);
std::vector<std::string> systemNames();
std::string occupancyName(Occupancy o); // "standard" | "assembly" | "hazardous" | "essential"
std::optional<Occupancy> occupancyFromName(const std::string& s);
std::vector<std::string> occupancyNames();

} // namespace kinstab
