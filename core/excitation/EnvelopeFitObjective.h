// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The envelope fit's objective (core/excitation/EnvelopeFit.h, docs/theory.md §7): at the
// half-cycle peaks (t_q, p_q), f = min_c sum (p_q - c e(t_q))^2 with e = exp(-alpha t) - exp(-beta
// t). For fixed (alpha, beta) c is linear least squares, c = <e,p> / <e,e>, so f depends on the two
// rates only (variable projection, Golub & Pereyra 1973). Coordinates: x = ln alpha and z, where
// r = beta / alpha - 1 is 1 + z below 1 and exp(z) above: toward beta -> alpha f is smooth in r
// (e tends to (beta - alpha) t exp(-alpha t)), toward beta -> infinity in ln r.

#include "core/excitation/EnvelopeFit.h"

#include <array>
#include <cstdint>
#include <limits>
#include <vector>

namespace kinstab {

struct FitPeaks {
    std::vector<double> time, value; // s, g
    std::vector<std::uint32_t> gap;  // samples since the peak before (the first: since t = 0)
    double dt = 0;                   // s, the motion's sample interval
    double sumSquares = 0;           // sum p_q^2, g^2
};
FitPeaks fitPeaks(const std::vector<PeakPoint>& p, double dt);

// f at (x, z) with its gradient and Hessian in (x, z).
struct FitPoint {
    double x = 0, z = 0;
    double sse = std::numeric_limits<double>::infinity(); // f, g^2
    double scale = 0;                                     // c, g
    std::array<double, 2> g{};
    std::array<double, 3> h{}; // xx, xz, zz
};
FitPoint evaluateFit(const FitPeaks& p, double x, double z);

double ratioOf(double z); // r = beta / alpha - 1
double zOfRatio(double r);

} // namespace kinstab
