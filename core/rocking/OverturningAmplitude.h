// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Which amplitudes of a motion family overturn a block: the smallest one, and the intervals of
// overturning amplitudes up to a maximum, so that a "safe cape" (Zhang & Makris 2001: amplitudes
// above an overturning one that do not overturn) shows. A scan at a fixed step; optionally a
// refinement where the block came close to overturning (below); then bisection of every change
// of outcome to a tolerance; bounded. A run in which the block leaves its base (the model cannot
// follow it further: RockingOutcome::LeavesBase) counts as overturning here: nothing shows it
// survives.
//
// Why refine. Near the boundary of overturning, overturning and standing intervals can be far
// thinner than any affordable scan step (the narrow bands beside the safe cape of Zhang & Makris
// 2001, Figs. 9-11; a one-sine pulse of omega_p / p = 2 on their block stands at 2.31-2.35
// alpha g between overturning amplitudes a 200-point scan to 2.5 g does not tell apart). Two
// continuous signs show where to look (refineDepth > 0):
//  - between two standing neighbours, max |theta| / alpha: where one of them rocked to at least
//    nearLevel alpha, the gap is halved, refineDepth times at most (down to a scan step /
//    2^refineDepth);
//  - between two overturning neighbours, the number of impacts before the fall: where it
//    differs they lie on different branches of overturning, whose meeting point (the block
//    hanging at theta = alpha) is bisected for, and a standing gap there is found unless it is
//    narrower than the tolerance.
// Every change of outcome found is bisected like the scan's. What neither sign shows (a gap
// between two overturning amplitudes of the same branch) can still be missed.

#include "core/rocking/BaseMotion.h"
#include "core/rocking/RockingModel.h"
#include "core/sweep/SweepControl.h"

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace kinstab {

// The base motion of a family at amplitude A (g, > 0): a pulse of that amplitude, a record
// scaled to that peak or by that factor.
using MotionFamily = std::function<std::unique_ptr<BaseMotion>(double amplitude)>;

// The refinement the command line, Python and the study engine use for the smallest overturning
// amplitude: a near gap halved down to 1/64 of the scan step (5 g / 200 / 64 = 4e-4 g with
// kinstab-cli's defaults), and the whole search stopped at 5000 runs (a pulse at about 30 us a
// run: 0.15 s; a 30 s record at about 2 ms: 10 s). With them the Zhang & Makris 2001 block's
// one-sine and one-cosine pulses at omega_p / p = 1.5 and 2 show every interval a 20,000-point
// scan shows, in 230 to 450 runs (tests/cli/tst_cli_rocking.cpp).
inline constexpr int kOverturningRefineDepth = 6;
inline constexpr long kOverturningMaxRuns = 5000;

struct OverturningSearch {
    double maxAmplitude = 5.0; // g (or the family's unit)
    int scanPoints = 200;      // equally spaced amplitudes in (0, maxAmplitude]
    double tolerance = 1e-4;   // relative, of each interval end
    int maxBisections = 60;
    int refineDepth = 0;    // 0: the plain scan; else halvings of a near gap (at most 30)
    double nearLevel = 0.5; // max |theta| / alpha from which a standing run is "near"
    long maxRuns = 1000000; // runs of the whole search; reaching it ends the search early
};

struct OverturningIntervals {
    // [from, to] of each interval of overturning amplitudes, increasing; the last one's `to` is
    // maxAmplitude when the largest amplitude scanned overturns (open to the maximum).
    std::vector<std::pair<double, double>> intervals;
    std::optional<double> critical() const; // the first `from`, none when nothing overturns
    long runs = 0;
    // The search stopped at OverturningSearch::maxRuns: what was not refined or bisected then
    // is as coarse as the work done so far (the intervals are still consistent).
    bool runLimitReached = false;
};

// Empty when the search's settings are usable, else why not (naming the setting).
std::string overturningSearchProblem(const OverturningSearch& s);

// Throws what simulateRocking throws, and std::invalid_argument for settings
// overturningSearchProblem refuses. control: progress (scan points done, of scanPoints) and
// cancel, which stops between runs and returns the intervals found so far (the caller tells a
// cancelled search by control->isCancelled()).
OverturningIntervals overturningIntervals(const RockingModel& model, const MotionFamily& family,
                                          const OverturningSearch& search = {},
                                          const SweepControl* control = nullptr);

} // namespace kinstab
