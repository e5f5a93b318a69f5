// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/sweep/SearchWork.h"

#include "core/base/SignificantDigits.h"
#include "core/base/TextInput.h"

#include <algorithm>
#include <cmath>

namespace kinstab {

double solverCostFactor(const Slab1DCase& c) {
    if (c.solver != SolverKind::Paper) return 1.0;
    return std::max(1.0, c.paperStepsPerPeriod / kPaperStepsPerExactHalfPeriod);
}

double sineHalfPeriods(const Slab1DCase& c, double amplitude, const SineWorkModel& m) {
    const double peak = amplitude * m.amplitudeFactor;
    if (!(peak > c.slab.mu)) return 0.0;
    double seconds = std::log(peak / c.slab.mu) / c.envelope.alpha;
    if (c.slab.duration) seconds = std::min(seconds, *c.slab.duration * c.tstar);
    return 2.0 * m.frequencyHz * seconds;
}

long searchRuns(double scanFrom, const CriticalSearch& s) {
    const double base = std::max(s.from, scanFrom);
    const double points = std::max(0.0, std::ceil((s.to - base) / s.scanStep));
    const double halvings = std::ceil(std::log2(std::max(s.scanStep / s.tolerance, 1.0)));
    return 1 + static_cast<long>(std::min(points, static_cast<double>(kMaxScanPoints))) +
           static_cast<long>(std::min(halvings, static_cast<double>(kMaxHalvings)));
}

double runWork(const Slab1DCase& c, double amplitude, const SineWorkModel& m) {
    return std::max(sineHalfPeriods(c, amplitude, m), kRunFloorHalfPeriods) * m.costFactor;
}

namespace {

InputProblem workProblem(double runs, double perRun, double limit, const std::string& what,
                         const SineWorkModel& m) {
    const double work = runs * perRun;
    if (work <= limit) return {};
    return {"frequency", m.frequencyHz, "Hz",
            what + " would walk up to " + significantDigits(work, 3) +
                " half-periods of the sine (" + significantDigits(runs, 3) + " runs of up to " +
                significantDigits(perRun, 3) + "; at most " + significantDigits(limit, 3) +
                "): lower the frequency or the amplitude, shorten the envelope (alpha) or the "
                "run (duration)"};
}

} // namespace

InputProblem checkRunWork(const Slab1DCase& c, double amplitude, const SineWorkModel& m) {
    return workProblem(1.0, runWork(c, amplitude, m), kMaxSearchWork, "a run there", m);
}

InputProblem checkSearchWork(const Slab1DCase& c, double scanFrom, const CriticalSearch& s,
                             const SineWorkModel& m) {
    return workProblem(static_cast<double>(searchRuns(scanFrom, s)), runWork(c, s.to, m),
                       kMaxSearchWork,
                       "an A_crit search there (up to " + formatDouble(s.to) +
                           " g; a coarser scan_step makes fewer runs)",
                       m);
}

SineWorkModel planarWork(const PlanarCase& c, double fxHz) {
    return {std::max(fxHz, c.fyHz), std::max(1.0, c.ayRatio), kPlanarCostFactor};
}

InputProblem checkPlanarRunWork(const PlanarCase& c, double ax, double fxHz) {
    // The bound reads the envelope, t*, mu and tau_out; planarWork gives the planar solver's cost.
    return checkRunWork(c.common, ax, planarWork(c, fxHz));
}

InputProblem checkSurfaceWork(const Slab1DCase& c, std::size_t points, double maxAmplitude,
                              const SineWorkModel& m) {
    return workProblem(static_cast<double>(points), runWork(c, maxAmplitude, m), kMaxSurfaceWork,
                       "a surface up to it", m);
}

} // namespace kinstab
