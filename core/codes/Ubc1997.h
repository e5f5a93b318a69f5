// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// UBC 1997 §1630.2, static force procedure at strength level (docs/codes.md §3):
// V = C_v I W / (R T) ≤ 2.5 C_a I W / R, ≥ 0.11 C_a I W, and in zone 4 ≥ 0.8 Z N_v I W / R;
// F_t = 0.07 T V ≤ 0.25 V (0 for T ≤ 0.7 s), F_x = (V − F_t) w_x h_x / Σ w_i h_i.

#include "core/codes/Building.h"
#include "core/codes/CodeResult.h"

#include <optional>

namespace kinstab {

enum class Ubc97Zone { Z1, Z2A, Z2B, Z3, Z4 };
enum class Ubc97Soil { SA, SB, SC, SD, SE }; // S_F needs a site-specific study

struct Ubc1997Inputs {
    Ubc97Zone zone = Ubc97Zone::Z4;
    Ubc97Soil soil = Ubc97Soil::SD;   // Table 16-J; S_D is the default when unknown
    double na = 1.0;                  // near-source factor N_a (zone 4 only)
    double nv = 1.0;                  // near-source factor N_v (zone 4 only)
    std::optional<double> importance; // I (Table 16-K); nullopt: from the occupancy
    double r = 8.5;                   // R (Table 16-N)
};

// Ranges the validator checks and the codes panel offers.
inline constexpr Range kUbc1997Na{1.0, 1.5};          // N_a, Table 16-S
inline constexpr Range kUbc1997Nv{1.0, 2.0};          // N_v, Table 16-T
inline constexpr Range kUbc1997Importance{1.0, 1.25}; // I, Table 16-K
inline constexpr Range kUbc1997R{1.0, 10.0};          // R, Table 16-N

std::string validateUbc1997(const Ubc1997Inputs& in); // empty when fine

double ubc97ZoneFactor(Ubc97Zone z);
std::string ubc97ZoneName(Ubc97Zone z); // "1" | "2A" | "2B" | "3" | "4"
std::optional<Ubc97Zone> ubc97ZoneFromName(const std::string& s);
std::string ubc97SoilName(Ubc97Soil s); // "SA" … "SE"
std::optional<Ubc97Soil> ubc97SoilFromName(const std::string& s);
double ubc97Ca(Ubc97Soil s, Ubc97Zone z, double na); // Table 16-Q
double ubc97Cv(Ubc97Soil s, Ubc97Zone z, double nv); // Table 16-R
double ubc1997Importance(Occupancy o);               // Table 16-K
double ubc1997FormulaPeriod(const Building& b);      // Method A, eq. 30-8

CodeResult ubc1997(const Building& b, const Ubc1997Inputs& in);

} // namespace kinstab
