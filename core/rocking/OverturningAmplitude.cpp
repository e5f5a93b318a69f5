// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/rocking/OverturningAmplitude.h"

#include "core/base/TextInput.h"
#include "core/rocking/RockingSolver.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace kinstab {

std::optional<double> OverturningIntervals::critical() const {
    if (intervals.empty()) return std::nullopt;
    return intervals.front().first;
}

namespace {

// One amplitude tried: whether it overturns, how close it came (max |theta| / alpha; 1 when it
// overturns) and its impacts before its fate was decided (which branch of overturning it is on).
struct Sample {
    double amplitude = 0;
    bool overturns = false;
    double closeness = 0;
    std::size_t impacts = 0;
};

struct Prober {
    const RockingModel& model;
    const MotionFamily& family;
    const OverturningSearch& search;
    const SweepControl* control;
    long runs = 0;
    bool limited = false;

    // Whether another run may start: not cancelled, and within the search's run budget.
    bool mayRun() {
        if (control && control->isCancelled()) return false;
        if (runs < search.maxRuns) return true;
        limited = true;
        return false;
    }
    Sample probe(double amplitude) {
        ++runs;
        const std::unique_ptr<BaseMotion> motion = family(amplitude);
        RockingRunOptions o;
        o.stopAtOverturnDecision = true;
        o.followOverturn = search.refineDepth > 0;
        const RockingResult r = simulateRocking(model, *motion, o);
        const bool over =
            r.outcome == RockingOutcome::Overturns || r.outcome == RockingOutcome::LeavesBase;
        return {amplitude, over, over ? 1.0 : r.maxThetaOverAlpha, r.impactTimes.size()};
    }
    // The change between lo (outcome lowOverturns) and hi (the other), narrowed to the
    // tolerance (relative): the last amplitude with lo's outcome and the first with hi's.
    std::pair<double, double> bisect(double lo, double hi, bool lowOverturns) {
        for (int i = 0; i < search.maxBisections && hi - lo > search.tolerance * hi && mayRun();
             ++i) {
            const double mid = 0.5 * (lo + hi);
            (probe(mid).overturns == lowOverturns ? lo : hi) = mid;
        }
        return {lo, hi};
    }
};

// The scan: amplitude 0 (a block at rest stays: it never overturns) and scanPoints amplitudes
// up to the maximum.
std::vector<Sample> scan(Prober& p) {
    const OverturningSearch& s = p.search;
    std::vector<Sample> out{Sample{}};
    for (int k = 1; k <= s.scanPoints && p.mayRun(); ++k) {
        out.push_back(p.probe(s.maxAmplitude * k / s.scanPoints));
        if (p.control && p.control->onProgress)
            p.control->onProgress(static_cast<std::size_t>(k),
                                  static_cast<std::size_t>(s.scanPoints));
    }
    return out;
}

// Between two overturning neighbours on different branches (a different number of impacts
// before the fall), bisect on the branch: where two branches meet the block hangs at its corner
// (theta = alpha) and a gap of standing amplitudes may lie. Every half whose ends still differ
// is searched (several branches may lie between two scan points), each down to the tolerance;
// a standing amplitude ends its half (the outcome bisection takes its edges). The amplitudes
// tried, increasing.
std::vector<Sample> branchSearch(Prober& p, const Sample& lo, const Sample& hi) {
    std::vector<Sample> tried;
    std::vector<std::pair<Sample, Sample>> halves{{lo, hi}};
    while (!halves.empty() && p.mayRun()) {
        const auto [a, b] = halves.back();
        halves.pop_back();
        if (b.amplitude - a.amplitude <= p.search.tolerance * b.amplitude) continue;
        const Sample m = p.probe(0.5 * (a.amplitude + b.amplitude));
        tried.push_back(m);
        if (!m.overturns) continue;
        if (m.impacts != a.impacts) halves.push_back({a, m});
        if (m.impacts != b.impacts) halves.push_back({m, b});
    }
    std::sort(tried.begin(), tried.end(),
              [](const Sample& x, const Sample& y) { return x.amplitude < y.amplitude; });
    return tried;
}

void searchBranches(Prober& p, std::vector<Sample>& samples) {
    std::vector<Sample> next{samples.front()};
    for (std::size_t i = 1; i < samples.size(); ++i) {
        const Sample& a = samples[i - 1];
        const Sample& b = samples[i];
        if (a.overturns && b.overturns && a.impacts != b.impacts)
            for (const Sample& m : branchSearch(p, a, b))
                next.push_back(m);
        next.push_back(b);
    }
    samples = std::move(next);
}

// Whether the gap between two neighbours is worth halving: both stand, one came near.
bool nearGap(const Sample& a, const Sample& b, double smallest, const OverturningSearch& s) {
    return !a.overturns && !b.overturns && std::max(a.closeness, b.closeness) >= s.nearLevel &&
           b.amplitude - a.amplitude > smallest;
}

// The branches' meeting points first; then every near gap halved, pass after pass, until none
// is left wider than a scan step / 2^refineDepth (refineDepth passes at most) or the run budget
// ends.
void refine(Prober& p, std::vector<Sample>& samples) {
    const OverturningSearch& s = p.search;
    if (s.refineDepth == 0) return;
    searchBranches(p, samples);
    const double smallest =
        1.000001 * s.maxAmplitude / s.scanPoints / std::ldexp(1.0, s.refineDepth);
    for (int pass = 0; pass < s.refineDepth; ++pass) {
        std::vector<Sample> next{samples.front()};
        bool added = false;
        for (std::size_t i = 1; i < samples.size(); ++i) {
            if (nearGap(samples[i - 1], samples[i], smallest, s) && p.mayRun()) {
                next.push_back(p.probe(0.5 * (samples[i - 1].amplitude + samples[i].amplitude)));
                added = true;
            }
            next.push_back(samples[i]);
        }
        samples = std::move(next);
        if (!added) return;
    }
}

// Every change of outcome between neighbours, bisected: an interval begins where the outcome
// turns to overturning (its first overturning amplitude, to the tolerance) and ends where it
// turns back (its last one); the last one reaches the maximum if the last sample overturns.
std::vector<std::pair<double, double>> intervalsOf(Prober& p, const std::vector<Sample>& samples) {
    std::vector<std::pair<double, double>> out;
    for (std::size_t i = 1; i < samples.size(); ++i) {
        const Sample& a = samples[i - 1];
        const Sample& b = samples[i];
        if (b.overturns && !a.overturns)
            out.push_back(
                {p.bisect(a.amplitude, b.amplitude, false).second, p.search.maxAmplitude});
        else if (a.overturns && !b.overturns)
            out.back().second = p.bisect(a.amplitude, b.amplitude, true).first;
    }
    return out;
}

} // namespace

std::string overturningSearchProblem(const OverturningSearch& s) {
    if (!(s.maxAmplitude > 0.0))
        return "max amplitude " + formatDouble(s.maxAmplitude) + ": must be > 0";
    if (s.scanPoints < 1 || s.scanPoints > 100000)
        return "scan points " + std::to_string(s.scanPoints) + ": must be 1 to 100000";
    if (!(s.tolerance > 0.0 && s.tolerance < 0.5))
        return "tolerance " + formatDouble(s.tolerance) + ": must be > 0 and < 0.5";
    if (s.maxBisections < 1 || s.maxBisections > 200)
        return "bisections " + std::to_string(s.maxBisections) + ": must be 1 to 200";
    if (s.refineDepth < 0 || s.refineDepth > 30)
        return "refine depth " + std::to_string(s.refineDepth) + ": must be 0 to 30";
    if (!(s.nearLevel > 0.0 && s.nearLevel <= 1.0))
        return "near level " + formatDouble(s.nearLevel) + ": must be > 0 and at most 1";
    if (s.maxRuns < 1 || s.maxRuns > 100000000)
        return "run limit " + std::to_string(s.maxRuns) + ": must be 1 to 100000000";
    return {};
}

OverturningIntervals overturningIntervals(const RockingModel& model, const MotionFamily& family,
                                          const OverturningSearch& search,
                                          const SweepControl* control) {
    if (const std::string e = overturningSearchProblem(search); !e.empty())
        throw std::invalid_argument("overturning search: " + e);
    Prober prober{model, family, search, control};
    std::vector<Sample> samples = scan(prober);
    refine(prober, samples);
    OverturningIntervals out;
    out.intervals = intervalsOf(prober, samples);
    out.runs = prober.runs;
    out.runLimitReached = prober.limited;
    return out;
}

} // namespace kinstab
