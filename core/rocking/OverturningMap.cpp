// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/rocking/OverturningMap.h"

#include "core/rocking/RockingSolver.h"
#include "core/sweep/ParallelFor.h"

#include <atomic>
#include <numbers>
#include <stdexcept>
#include <string>

namespace kinstab {

namespace {

std::vector<double> axis(double lo, double hi, int n) {
    std::vector<double> v(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i)
        v[static_cast<std::size_t>(i)] = n == 1 ? lo : lo + (hi - lo) * i / (n - 1);
    return v;
}

void checkSpec(const OverturningMapSpec& s) {
    auto bad = [](const std::string& what) {
        throw std::invalid_argument("overturning map: " + what);
    };
    if (!(s.amplitudeMin > 0.0 && s.amplitudeMax >= s.amplitudeMin && s.amplitudeMax <= 1e4))
        bad("amplitudes a_p/(alpha g) must satisfy 0 < min <= max <= 10000");
    if (!(s.frequencyMin > 0.0 && s.frequencyMax >= s.frequencyMin && s.frequencyMax <= 1e4))
        bad("frequencies omega_p/p must satisfy 0 < min <= max <= 10000");
    if (s.amplitudePoints < 1 || s.frequencyPoints < 1 || s.amplitudePoints > 4097 ||
        s.frequencyPoints > 4097)
        bad("points per axis must be between 1 and 4097");
}

} // namespace

OverturningMap overturningMap(const RockingModel& model, const OverturningMapSpec& spec,
                              const SweepControl* control) {
    checkSpec(spec);
    if (auto p = checkRockingModel(model); !p.empty()) throw std::invalid_argument(describe(p));
    OverturningMap map;
    map.spec = spec;
    map.amplitudes = axis(spec.amplitudeMin, spec.amplitudeMax, spec.amplitudePoints);
    map.frequencies = axis(spec.frequencyMin, spec.frequencyMax, spec.frequencyPoints);
    const std::size_t n = map.amplitudes.size() * map.frequencies.size();
    map.overturns.assign(n, 0);
    map.maxThetaOverAlpha.assign(n, 0.0f);
    const double alpha = blockAlpha(model.block), p = blockFrequency(model.block);
    std::atomic<std::size_t> done{0};
    RockingRunOptions options;
    options.stopAtOverturnDecision = true;
    parallelFor(n, spec.threads, control, [&](std::size_t k) {
        const std::size_t i = k / map.amplitudes.size(), j = k % map.amplitudes.size();
        const double wp = map.frequencies[i] * p;
        Pulse pulse;
        pulse.shape = spec.shape;
        pulse.amplitude = -map.amplitudes[j] * alpha; // tips the block towards +x
        pulse.frequencyHz = wp / (2.0 * std::numbers::pi);
        pulse.durationS = 2.0 * std::numbers::pi / wp;
        const RockingResult r = simulateRocking(model, PulseMotion(pulse), options);
        map.overturns[k] = r.outcome == RockingOutcome::Overturns    ? 1
                           : r.outcome == RockingOutcome::LeavesBase ? 2
                                                                     : 0;
        map.maxThetaOverAlpha[k] = static_cast<float>(r.maxThetaOverAlpha);
        const std::size_t d = ++done;
        if (control && control->onProgress) control->onProgress(d, n);
    });
    map.complete = !(control && control->isCancelled()) && done.load() == n;
    return map;
}

} // namespace kinstab
