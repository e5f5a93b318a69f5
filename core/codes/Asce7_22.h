// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// ASCE/SEI 7-22 §12.8, equivalent lateral force procedure (docs/codes.md §5), with the two-period
// spectrum (S_DS, S_D1, T_L) entered as the USGS service gives it for the site class:
// C_s = max(min(S_DS/(R/I_e), S_D1/(T R/I_e) or S_D1 T_L/(T² R/I_e)), 0.044 S_DS I_e, 0.01
// [, 0.5 S_1/(R/I_e) where S_1 ≥ 0.6]), T ≤ C_u T_a, F_x = C_vx V with exponent k.

#include "core/codes/Building.h"
#include "core/codes/CodeResult.h"

#include <optional>
#include <string>

namespace kinstab {

struct Asce7Inputs {
    double sds = 1.0;            // S_DS, g
    double sd1 = 0.6;            // S_D1, g
    std::optional<double> s1;    // S_1 (MCE_R, 1 s), g: only for the eq. 12.8-6 floor
    double tl = 8.0;             // long-period transition period T_L, s
    std::string siteClass = "D"; // A B BC C CD D DE E F or Default (recorded; S_DS/S_D1 hold it)
    std::optional<int> riskCategory;  // I–IV (Table 1.5-1); nullopt: from the occupancy
    std::optional<double> importance; // I_e; nullopt: from the risk category (Table 1.5-2)
    double r = 6.0;                   // response modification coefficient R (Table 12.2-1)
};

// Ranges the validator checks and the codes panel offers.
inline constexpr Range kAsce7Sd{0.0, 5.0, true};   // S_DS and S_D1, g
inline constexpr Range kAsce7S1{0.0, 5.0};         // S_1, g
inline constexpr Range kAsce7Tl{0.0, 20.0, true};  // T_L, s
inline constexpr Range kAsce7Importance{1.0, 1.5}; // I_e, Table 1.5-2
inline constexpr Range kAsce7R{1.0, 10.0};         // R, Table 12.2-1

std::string validateAsce7(const Asce7Inputs& in); // empty when fine

int asceRiskCategory(Occupancy o);
double asceImportance(int riskCategory);          // Table 1.5-2
double asceUpperLimitCoefficient(double sd1);     // C_u, Table 12.8-1 (interpolated)
double asce7ApproximatePeriod(const Building& b); // T_a = C_t h_n^x, Table 12.8-2
std::vector<std::string> asceSiteClassNames();

CodeResult asce7_22(const Building& b, const Asce7Inputs& in);

} // namespace kinstab
