// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// UBC 1976 §2312, equivalent static force method (docs/codes.md §2): V = Z I K C S W,
// C = 1/(15 √T) ≤ 0.12, S from T/T_s (1.5 when T_s is unknown), C S ≤ 0.14,
// F_t = 0.07 T V ≤ 0.25 V (0 for T ≤ 0.7 s), F_x = (V − F_t) w_x h_x / Σ w_i h_i.

#include "core/codes/Building.h"
#include "core/codes/CodeResult.h"

#include <optional>

namespace kinstab {

struct Ubc1976Inputs {
    int zone = 4;                     // 0–4 (Figure 1); zone 4 first appeared in 1976
    std::optional<double> importance; // I (Table 23-K); nullopt: from the occupancy
    double k = 0.80;                  // K (Table 23-I); 0.80 = dual system (the paper)
    std::optional<double> sitePeriod; // T_s, s; nullopt: not established, S = 1.5
};

// Ranges the validator checks and the codes panel offers.
inline constexpr Range kUbc1976Importance{1.0, 1.5};        // I, Table 23-K
inline constexpr Range kUbc1976K{0.67, 2.5};                // K, Table 23-I
inline constexpr Range kUbc1976SitePeriod{0.0, 10.0, true}; // T_s, s

std::string validateUbc1976(const Ubc1976Inputs& in); // empty when fine

double ubc1976ZoneFactor(int zone);             // Z: 0, 3/16, 3/8, 3/4, 1
double ubc1976Importance(Occupancy o);          // Table 23-K
double ubc1976FormulaPeriod(const Building& b); // eq. 12-3 / 12-3A
double ubc1976SiteFactor(double period, std::optional<double> sitePeriod);

// Throws InputError on bad building or inputs.
CodeResult ubc1976(const Building& b, const Ubc1976Inputs& in);

} // namespace kinstab
