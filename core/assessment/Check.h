// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One check of a project's assessment (core/assessment/Assessment.h): a demand and a capacity
// expressed in the same intensity, their margin (capacity / demand) and a verdict in words that
// say what was compared. A check may hold more than one comparison (a floor check compares the
// ground intensity through the building model, then the code's own floor formula). The first is
// the check's own; another governs only where it disagrees (fails while the first holds), so
// the verdict is the cautious one and the margin otherwise follows the first.

#include <optional>
#include <string>
#include <vector>

namespace kinstab {

// What the check rests on: the enveloped sine of ch. IV, a record (through the floor filter or
// not), the building's floor motions under a ground record, the planar slab of ch. VI, or a
// study's collapse fragility integrated against the site's hazard curve (the annual rate of the
// slab falling against a target rate).
// A free-standing block on a level of the building (Block) is checked like the slab on its floor.
enum class CheckBasis { Sine, Record, Floors, Planar, Risk, Block };
// "sine" | "record" | "floors" | "planar" | "risk" | "block"
std::string checkBasisName(CheckBasis b);

// The code level the demand belongs to: the design level (the paper's ch. V question: does the
// structure reach its code strength before the slab slides off?) or MCE_R (does the slab stay
// seated?); a risk check's demand is no level of ground motion but the rate of collapse over
// every level of the hazard curve.
enum class CheckLevel { Design, MceR, Collapse };
std::string checkLevelName(CheckLevel l); // "design" | "mce_r" | "collapse"

// The unit of a risk check's demand and capacity.
inline constexpr const char* kAnnualRateUnit = "1/yr";

struct Comparison {
    std::string intensity;          // what both numbers measure: "ground PGA", ...
    std::string unit;               // "g"
    std::string demandName;         // "0.4 S_MS (ASCE 7-22 §13.3.1 at grade)"
    double demand = 0;              //
    std::string capacityName;       // "critical ground PGA of the slab on level 16"
    std::optional<double> capacity; // none: nothing collapses up to searchLimit
    double searchLimit = 0;         // the capacity's search bound, in the same unit
    std::optional<double> margin;   // capacity / demand; none when no capacity
    double orderingMargin() const;  // margin, or searchLimit / demand when no collapse was found
    bool holds() const;             // demand below capacity (or below the search limit)
};

// The margin as every front end prints it: "1.21", or "> 2.50" when no collapse was found.
std::string marginText(const Comparison& x);
// A demand or capacity as every front end's table prints it: accelerations (g) to 3 decimals,
// annual rates (1/yr) to 3 significant digits ("2.01e-04"), which 3 decimals would print as 0.
std::string quantityText(const Comparison& x, double value);

struct Check {
    std::string id; // BASIS.CODE[.LEVEL]: "sine.ubc1976", "floors.asce7_22.mce_r"
    CheckBasis basis = CheckBasis::Sine;
    std::string code;      // "ubc1976"
    std::string codeTitle; // "UBC 1976 §2312"
    CheckLevel level = CheckLevel::Design;
    std::string model;                   // the slab model and, for floors, the building model
    std::string excitation;              // what drives it
    std::vector<Comparison> comparisons; // at least one
    std::size_t governingComparison = 0; // the first, or a failing one where they disagree
    bool holds = true;                   // every comparison holds
    std::string verdict;                 // words: see verdictWords in Assessment.cpp

    const Comparison& governing() const { return comparisons.at(governingComparison); }
};

// Sets holds (every comparison holds) and governingComparison: the first comparison is the
// check's own; another governs only where it disagrees (does not hold while the first does),
// then the failing one with the smallest margin. The verdict is the caller's.
void settleComparisons(Check& c);

} // namespace kinstab
