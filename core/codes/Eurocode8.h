// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// EN 1998-1:2004 lateral force method of analysis, §4.3.3.2 (docs/codes.md §6), with the
// recommended spectrum parameters (Tables 3.2, 3.3): F_b = S_d(T_1) m λ,
// F_i = F_b z_i m_i / Σ z_j m_j (linear mode shape).

#include "core/codes/Building.h"
#include "core/codes/CodeResult.h"

#include <optional>

namespace kinstab {

enum class Ec8Ground { A, B, C, D, E };

struct Eurocode8Inputs {
    Ec8Ground ground = Ec8Ground::C;    // Table 3.1
    int spectrumType = 1;               // 1: M_s > 5.5 dominates; 2: M_s ≤ 5.5
    double agr = 0.25;                  // reference peak ground acceleration a_gR on type A, g
    std::optional<int> importanceClass; // I–IV; nullopt: from the occupancy
    std::optional<double> gammaI;       // γ_I; nullopt: recommended value of the class
    double q = 3.9;                     // behaviour factor (DCM frame/dual: 3.0 α_u/α_1 = 3.9)
    double beta = 0.2;                  // lower-bound factor β (recommended 0.2)
    bool regularInElevation = true;     // the lateral force method needs it (§4.3.3.2.1)
};

struct Ec8SpectrumParameters {
    double s = 1, tb = 0, tc = 0, td = 0;
};

// Ranges the validator checks and the codes panel offers.
inline constexpr Range kEc8Agr{0.0, 2.0, true}; // a_gR, g
inline constexpr Range kEc8GammaI{0.5, 2.0};    // γ_I
inline constexpr Range kEc8Q{1.0, 8.0};         // q
inline constexpr Range kEc8Beta{0.0, 1.0};      // β

std::string validateEurocode8(const Eurocode8Inputs& in); // empty when fine

std::string ec8GroundName(Ec8Ground g); // "A" … "E"
std::optional<Ec8Ground> ec8GroundFromName(const std::string& s);
Ec8SpectrumParameters ec8Spectrum(Ec8Ground g, int spectrumType); // Tables 3.2 / 3.3
double ec8DesignSpectrum(double t, double ag, const Ec8SpectrumParameters& p, double q,
                         double beta);           // S_d(T) / g, eqs. 3.13–3.16
double ec8ImportanceFactor(int importanceClass); // recommended γ_I: 0.8, 1.0, 1.2, 1.4
int ec8ImportanceClass(Occupancy o);
double eurocode8FormulaPeriod(const Building& b); // T_1 = C_t H^(3/4), §4.3.3.2.2(3)

CodeResult eurocode8(const Building& b, const Eurocode8Inputs& in);

} // namespace kinstab
