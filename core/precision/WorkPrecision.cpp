// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/precision/WorkPrecision.h"

#include "core/base/InternalError.h"
#include "core/base/Stopwatch.h"
#include "core/excitation/EnvelopedSine.h"
#include "core/slab/ExactSolver.h"
#include "core/slab/LongDoubleReplay.h"
#include "core/slab/PaperRk4Solver.h"
#include "core/slab/RegularizedSolver.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <numbers>
#include <sstream>

namespace kinstab {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

Slab1DCase modelWith(EnvelopePreset preset) {
    Slab1DCase c;
    c.envelope = Envelope::fromPreset(preset);
    return c; // mu = 0.6, t* = 0.099, limit 1: the paper's defaults
}

// One run of a case: its excitation and the reference result.
struct Run {
    std::unique_ptr<EnvelopedSine> a;
    SlabParams params;
    SlabResult solver; // the exact solver at tolerance 0
    SlabResult ref;    // its long double replay's tau_c and residual; the solver's work counts
    double endTau = 0; // where a model without sticking is stopped (regularized)
};

using Solve = std::function<SlabResult(const Run&)>;

struct Setting {
    std::string solver, label;
    double parameter;
    Solve solve;
};

double periodOf(const EnvelopedSine& a) {
    return 2.0 * std::numbers::pi / a.omega();
}

// First half-period start after which |a| < mu for good: nothing can start there.
double quietAfter(const EnvelopedSine& a, double mu) {
    const double half = 0.5 * periodOf(a);
    double tau = 0.0;
    while (a.boundAfter(tau) >= mu && tau < 1e7)
        tau += half;
    return tau;
}

std::vector<Run> referenceRuns(const WorkPrecisionCase& c) {
    std::vector<Run> runs;
    for (double amplitude : c.amplitudes) {
        Run r;
        r.a = std::make_unique<EnvelopedSine>(c.model.envelope, amplitude, c.frequencyHz,
                                              c.model.tstar);
        r.params = c.model.slab;
        SlabEventLog events;
        r.solver = solveExact(*r.a, r.params, {}, &events); // eventTolerance 0: to a few ulps
        r.ref = r.solver;
        const ReplayResult replay = replayInLongDouble(*r.a, r.params, events.events);
        if (!replay.ok || replay.outcome != r.solver.outcome)
            throw InternalError("work-precision reference for case " + c.id +
                                ", A = " + std::to_string(amplitude) + " g: " + replay.failure);
        r.ref.tauC = static_cast<double>(replay.tauC);
        r.ref.residualDelta = static_cast<double>(replay.residualDelta);
        r.endTau = r.ref.outcome == Outcome::Stable ? r.ref.tauEnd : quietAfter(*r.a, r.params.mu);
        runs.push_back(std::move(r));
    }
    return runs;
}

std::vector<Setting> settings(bool regularized) {
    std::vector<Setting> s;
    for (int n = 16; n <= 1024; n *= 2) {
        s.push_back({"paper", "H=T/" + std::to_string(n), 1.0 / n, [n](const Run& r) {
                         PaperSettings p;
                         p.step = periodOf(*r.a) / n;
                         return solvePaperRk4(*r.a, r.params, p);
                     }});
    }
    for (int e = 2; e <= 12; e += 2) {
        const double tol = std::pow(10.0, -e);
        char label[32];
        std::snprintf(label, sizeof label, "tol=1e-%02d", e);
        s.push_back({"exact", label, tol, [tol](const Run& r) {
                         RunOptions o;
                         o.eventTolerance = tol;
                         return solveExact(*r.a, r.params, o);
                     }});
    }
    if (!regularized) return s;
    for (int e = 1; e <= 3; ++e) {
        const double c = std::pow(10.0, -e);
        char label[32];
        std::snprintf(label, sizeof label, "eps=1e-%02d mu/w", e);
        s.push_back({"regularized", label, c, [c](const Run& r) {
                         RegularizedSettings g;
                         g.width = c * r.params.mu / r.a->omega();
                         g.period = periodOf(*r.a);
                         g.endTau = r.endTau;
                         return solveRegularized(*r.a, r.params, g);
                     }});
    }
    return s;
}

// Errors of one setting on one case against the references.
void measureErrors(WorkPrecisionRow& row, const std::vector<Run>& runs, const Setting& s) {
    row.points = static_cast<int>(runs.size());
    row.tauCError = kNaN;
    row.residualError = kNaN;
    row.eventMismatch = s.solver == "regularized" ? -1 : 0;
    row.accelEvaluations = 0;
    auto maxNan = [](double acc, double x) { return std::isnan(acc) ? x : std::max(acc, x); };
    for (const Run& r : runs) {
        const SlabResult got = s.solve(r);
        row.accelEvaluations += got.work.accelEvaluations;
        if (row.eventMismatch >= 0)
            row.eventMismatch += std::labs(got.work.events - r.ref.work.events);
        if (got.outcome != r.ref.outcome) {
            ++row.outcomeMismatches;
            row.error = maxNan(row.error, 1.0);
        } else if (got.outcome == Outcome::Collapsed) {
            const double e = std::abs(got.tauC - r.ref.tauC);
            row.tauCError = maxNan(row.tauCError, e);
            row.error = maxNan(row.error, e / r.ref.tauC);
        } else {
            const double e = std::abs(got.residualDelta - r.ref.residualDelta);
            row.residualError = maxNan(row.residualError, e);
            row.error = maxNan(row.error, e / r.params.limit);
        }
    }
}

// Wall time of one pass over the case's runs: passes are looped so that one timed sample
// lasts at least 2 ms (the clock's resolution and call overheads vanish), then divided.
TimingStats measureTime(const std::vector<Run>& runs, const Setting& s, int repeats) {
    static volatile double sink = 0.0; // keeps the optimizer from dropping the runs
    auto pass = [&] {
        for (const Run& r : runs)
            sink = sink + s.solve(r).tauEnd;
    };
    const auto t0 = SteadyClock::now();
    pass();
    const double once = secondsSince(t0);
    const int loops =
        static_cast<int>(std::clamp(std::ceil(2e-3 / std::max(once, 1e-9)), 1.0, 1e4));
    if (once > 0.5) repeats = std::min(repeats, 3);
    TimingStats t = timeRuns(
        [&] {
            for (int i = 0; i < loops; ++i)
                pass();
        },
        repeats);
    t.minSeconds /= loops;
    t.medianSeconds /= loops;
    t.medianCpuSeconds /= loops;
    return t;
}

void setOrders(std::vector<WorkPrecisionRow>& rows) {
    for (std::size_t i = 0; i < rows.size(); ++i) {
        rows[i].order = kNaN;
        if (i == 0) continue;
        const WorkPrecisionRow& p = rows[i - 1];
        const WorkPrecisionRow& r = rows[i];
        if (p.caseId != r.caseId || p.solver != r.solver) continue;
        if (!(p.error > 0.0) || !(r.error > 0.0)) continue;
        rows[i].order = std::log(p.error / r.error) / std::log(p.parameter / r.parameter);
    }
}

} // namespace

std::vector<WorkPrecisionCase> workPrecisionCases() {
    std::vector<WorkPrecisionCase> c;
    WorkPrecisionCase grid{"paper-1Hz",
                           "moderate envelope, mu 0.6, t* 0.099 s, f 1 Hz, A 0.90..1.50 g by 0.05 "
                           "(the paper's grid at 1 Hz; stable up to 0.95, collapse from 1.00)",
                           modelWith(EnvelopePreset::Moderate),
                           {},
                           1.0};
    for (int i = 0; i <= 12; ++i)
        grid.amplitudes.push_back(0.90 + 0.05 * i);
    c.push_back(grid);
    c.push_back(
        {"grazing",
         "moderate, f 1 Hz, A = mu (1 + 1e-4) = 0.60006 g: one slip of about 3 sqrt(delta/k) "
         "at the main peak (docs/theory.md §6.6 case 3), residual ~2e-7",
         modelWith(EnvelopePreset::Moderate),
         {0.6 * (1.0 + 1e-4)},
         1.0});
    c.push_back(
        {"chattering",
         "fast envelope, f 10 Hz, A 0.62 g: ~100 near-grazing slips, each followed by a stick",
         modelWith(EnvelopePreset::Fast),
         {0.62},
         10.0});
    c.push_back({"high-frequency",
                 "moderate, f 20 Hz, A 100 g: ~1650 slips and reversals, stable at tau ~416",
                 modelWith(EnvelopePreset::Moderate),
                 {100.0},
                 20.0});
    c.push_back({"long-duration",
                 "fast envelope (alpha 0.01/s), f 1 Hz, A 0.95 g: ~100 slips up to tau ~500",
                 modelWith(EnvelopePreset::Fast),
                 {0.95},
                 1.0});
    return c;
}

WorkPrecisionStudy runWorkPrecisionStudy(const WorkPrecisionOptions& options) {
    WorkPrecisionStudy study;
    study.cases = workPrecisionCases();
    study.reference =
        "the exact solver's event sequence replayed in long double (64-bit significand) "
        "closed forms, each event time solved again; largest |double exact solver at "
        "tolerance 0 - reference| (tau_c, delta)";
    const std::vector<Setting> all = settings(options.includeRegularized);
    const std::size_t total = study.cases.size() * all.size();
    for (const WorkPrecisionCase& c : study.cases) {
        const std::vector<Run> runs = referenceRuns(c);
        for (const Run& r : runs) {
            const double gap = r.ref.outcome == Outcome::Collapsed
                                   ? std::abs(r.solver.tauC - r.ref.tauC)
                                   : std::abs(r.solver.residualDelta - r.ref.residualDelta);
            study.referenceConvergence = std::max(study.referenceConvergence, gap);
        }
        for (const Setting& s : all) {
            if (options.cancelled && options.cancelled()) {
                study.cancelled = true;
                return study;
            }
            WorkPrecisionRow row;
            row.caseId = c.id;
            row.solver = s.solver;
            row.setting = s.label;
            row.parameter = s.parameter;
            measureErrors(row, runs, s);
            row.timing = measureTime(runs, s, options.repeats);
            study.rows.push_back(row);
            if (options.onProgress) options.onProgress(study.rows.size(), total);
        }
    }
    setOrders(study.rows);
    return study;
}

namespace {
std::string num(double x, const char* fmt = "%.3e") {
    if (std::isnan(x)) return "nan";
    char b[48];
    std::snprintf(b, sizeof b, fmt, x);
    return b;
}
} // namespace

std::string workPrecisionCsv(const WorkPrecisionStudy& s) {
    std::ostringstream o;
    o << "case,solver,setting,parameter,runs,outcome_mismatches,event_mismatch,tau_c_error,"
         "residual_error,error,order,wall_min_s,wall_median_s,cpu_median_s,timed_runs,accel_"
         "evals\n";
    for (const WorkPrecisionRow& r : s.rows)
        o << r.caseId << ',' << r.solver << ',' << r.setting << ',' << num(r.parameter, "%.6g")
          << ',' << r.points << ',' << r.outcomeMismatches << ','
          << (r.eventMismatch < 0 ? std::string() : std::to_string(r.eventMismatch)) << ','
          << num(r.tauCError, "%.6e") << ',' << num(r.residualError, "%.6e") << ','
          << num(r.error, "%.6e") << ',' << num(r.order, "%.3f") << ','
          << num(r.timing.minSeconds, "%.6e") << ',' << num(r.timing.medianSeconds, "%.6e") << ','
          << num(r.timing.medianCpuSeconds, "%.6e") << ',' << r.timing.runs << ','
          << r.accelEvaluations << '\n';
    return o.str();
}

std::string workPrecisionText(const WorkPrecisionStudy& s) {
    std::ostringstream o;
    o << "Cases:\n";
    for (const WorkPrecisionCase& c : s.cases)
        o << "  " << c.id << ": " << c.description << "\n";
    o << "Reference: " << s.reference << ": " << num(s.referenceConvergence, "%.1e") << "\n";
    o << "error = max over runs of |tau_c - ref|/ref (collapsed), |delta_res - ref|/limit "
         "(stable), 1 for a wrong outcome; time = one pass over the case's runs\n\n";
    char line[256];
    std::snprintf(line, sizeof line, "%-15s %-11s %-16s %4s %5s %7s %9s %9s %9s %6s %10s %10s\n",
                  "case", "solver", "setting", "runs", "wrong", "events", "tau_c err", "resid err",
                  "error", "order", "min time s", "median s");
    o << line;
    for (const WorkPrecisionRow& r : s.rows) {
        std::snprintf(
            line, sizeof line, "%-15s %-11s %-16s %4d %5d %7s %9s %9s %9s %6s %10s %10s\n",
            r.caseId.c_str(), r.solver.c_str(), r.setting.c_str(), r.points, r.outcomeMismatches,
            r.eventMismatch < 0 ? "n/a" : std::to_string(r.eventMismatch).c_str(),
            num(r.tauCError, "%.2e").c_str(), num(r.residualError, "%.2e").c_str(),
            num(r.error, "%.2e").c_str(), num(r.order, "%.2f").c_str(),
            num(r.timing.minSeconds, "%.3e").c_str(), num(r.timing.medianSeconds, "%.3e").c_str());
        o << line;
    }
    return o.str();
}

} // namespace kinstab
