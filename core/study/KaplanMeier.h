// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The empirical collapse fragility of a suite whose records are censored at different
// intensities: the product-limit estimate (Kaplan & Meier 1958, "Nonparametric estimation from
// incomplete observations", JASA 53(282)) with the records that never collapse right-censored at
// their limit intensity:
//   F(x) = 1 - prod over collapse intensities t_i <= x of (1 - d_i / n_i),
// d_i the records collapsing at t_i, n_i those still "at risk" there (collapse or censoring
// intensity >= t_i; a record censored at t_i counts as at risk at t_i). Without censoring below
// x this is the plain empirical fraction (collapses <= x) / (all records).

#include "core/study/LognormalFit.h"

#include <vector>

namespace kinstab {

struct KaplanMeierStep {
    double intensity = 0;   // g, a distinct collapse intensity
    double probability = 0; // F just after it
};

// One step per distinct collapse intensity, ascending.
std::vector<KaplanMeierStep> kaplanMeier(const CensoredSample& s);

} // namespace kinstab
