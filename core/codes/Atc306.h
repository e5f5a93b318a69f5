// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// ATC 3-06 (1978) Chapter 4, equivalent lateral force procedure (docs/codes.md §4):
// C_s = 1.2 A_v S / (R T^(2/3)) ≤ 2.5 A_a / R (≤ 2.0 A_a / R on S3 soil with A_a ≥ 0.3),
// F_x = C_vx V with C_vx = w_x h_x^k / Σ w_i h_i^k. No importance factor, no top force.

#include "core/codes/Building.h"
#include "core/codes/CodeResult.h"

#include <optional>

namespace kinstab {

enum class AtcSoil { S1, S2, S3 }; // Table 3-A: S = 1.0, 1.2, 1.5

struct Atc306Inputs {
    std::optional<int> mapArea; // 1–7 (Table 1-B); when set, A_a = A_v from the table
    double aa = 0.40;           // effective peak acceleration A_a, g
    double av = 0.40;           // effective peak velocity-related acceleration A_v, g
    AtcSoil soil = AtcSoil::S3; // the paper's 30 ft of soft-to-medium clay
    double r = 5.5;             // response modification factor R (Table 3-B)
};

// Ranges the validator checks and the codes panel offers.
inline constexpr Range kAtc306Acceleration{0.0, 1.0, true}; // A_a and A_v, g
inline constexpr Range kAtc306R{1.0, 10.0};                 // R, Table 3-B

std::string validateAtc306(const Atc306Inputs& in); // empty when fine

double atcMapAreaCoefficient(int mapArea); // Table 1-B
double atcSoilFactor(AtcSoil s);           // Table 3-A
std::string atcSoilName(AtcSoil s);        // "S1" | "S2" | "S3"
std::optional<AtcSoil> atcSoilFromName(const std::string& s);
double atc306FormulaPeriod(const Building& b); // §4.2.2: C_T h_n^(3/4) or 0.05 h_n / √L

CodeResult atc306(const Building& b, const Atc306Inputs& in);

} // namespace kinstab
