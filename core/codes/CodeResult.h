// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What every code module returns (docs/theory.md §9): base shear coefficient, story forces, the
// top-floor ratio F_top / w_top and the trail of every coefficient used, with its clause.

#include "core/base/Range.h"
#include "core/codes/Building.h"
#include "core/codes/CodeCatalog.h"

#include <optional>
#include <string>
#include <vector>

namespace kinstab {

struct TrailEntry {
    std::string name;   // "period coefficient"
    std::string symbol; // "C"
    double value = 0;
    std::string clause; // "UBC 1976 §2312(d), eq. 12-2"
};

struct CodeResult {
    std::string code;                // "ubc1976" | "atc306" | "ubc1997" | "asce7_22" | "ec8"
    std::string title;               // "UBC 1976 §2312"
    double periodSeconds = 0;        // T used for the base shear
    std::string periodSource;        // "entered", "formula", "entered, capped at ..."
    double baseShearCoefficient = 0; // V / W
    std::vector<double> storyForces; // F_i / w_i per level, bottom first (top last)
    double topRatio = 0;             // F_n / w_n as the code requires it
    std::optional<double> topRatioWithoutFt; // UBC: F_n / w_n with F_t left off (the paper's)
    bool applicable = true;                  // false when outside the method's applicability limits
    std::vector<TrailEntry> trail;
    std::vector<std::string> notes; // caps that governed, ranges left, assumptions
};

// Vertical distribution F_x = share · w_x h_x^k / Σ w_i h_i^k (UBC eq. 12-7 with k = 1,
// ATC 3-06 eq. 4-6a, ASCE 7 eq. 12.8-12, EC8 eq. 4.11), returned as F_x / w_x per level.
// share = (V − F_t) / W; weights in any unit, heights above the base.
std::vector<double> distributedRatios(const std::vector<double>& weights,
                                      const std::vector<double>& heights, double k, double share);

// Opens a code's result after checking the building and the code's inputs (inputError: the
// code's validate message, empty when fine): throws InputError before anything is computed.
CodeResult beginCodeResult(const Building& b, const std::string& inputError, const CodeInfo& code);

// UBC 1976 eqs. 12-6/12-7 and UBC 1997 eqs. 30-14/30-15: V − F_t spread linearly with height,
// F_t added at level n. Ratios F_x / w_x, bottom first; topWithoutFt leaves F_t off (the
// paper's 0.140).
struct TopForceDistribution {
    std::vector<double> ratios;
    double topWithoutFt = 0;
};
TopForceDistribution distributeWithTopForce(const Building& b, double v, double ft);

// k of ATC 3-06 §4.3 and ASCE 7 §12.8.3: 1 up to 0.5 s, 2 from 2.5 s, linear in between.
double distributionExponent(double periodSeconds);

// Throws InputError "field = value: must be ..." unless lo <= x <= hi (and finite).
void requireRange(const std::string& field, double x, double lo, double hi,
                  const std::string& unit = {});
// Same with an open lower bound: lo < x <= hi.
void requireAbove(const std::string& field, double x, double lo, double hi,
                  const std::string& unit = {});
// requireRange or requireAbove, as the range's lower bound is closed or open.
void requireIn(const std::string& field, double x, Range r, const std::string& unit = {});

} // namespace kinstab
