// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/precision/PlanarPrecision.h"

#include "core/slab/MoreauSolver2D.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

namespace kinstab {

namespace {
constexpr double kRefRelTol = 1e-13, kRefAbsTol = 1e-15; // the solver's tightest setting
constexpr double kMoreauStep = 1e-3;                     // tau; Richardson with 2e-3

PlanarCase withTolerance(PlanarCase c, double relTol, double absTol) {
    c.solver = PlanarOptions{};
    c.solver.relTol = relTol;
    c.solver.absTol = absTol;
    return c;
}

std::vector<PlanarResult> runAll(const PlanarPrecisionCase& c, const PlanarCase& model) {
    std::vector<PlanarResult> out;
    for (double a : c.amplitudes)
        out.push_back(runPlanar(model, a, c.fxHz));
    return out;
}

bool ends(const PlanarResult& r) {
    return r.slab.outcome == Outcome::Collapsed || r.slab.outcome == Outcome::LiftOff;
}

// The 1-DOF study's error: |tau_c - ref| / ref (collapsed), |delta - ref| / limit (stable, both
// components), 1 for a wrong outcome or exit side.
void score(WorkPrecisionRow& row, const std::vector<PlanarResult>& runs,
           const std::vector<PlanarResult>& ref, const PlanarCase& c) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    row.tauCError = row.residualError = nan;
    row.error = 0.0;
    row.eventMismatch = 0;
    for (std::size_t k = 0; k < runs.size(); ++k) {
        const PlanarResult &r = runs[k], &q = ref[k];
        row.eventMismatch += std::labs(r.slab.work.events - q.slab.work.events);
        if (r.slab.outcome != q.slab.outcome || r.exitSide != q.exitSide) {
            ++row.outcomeMismatches;
            row.error = 1.0;
            continue;
        }
        if (ends(r)) {
            const double e = std::abs(r.slab.tauC - q.slab.tauC);
            row.tauCError = std::isnan(row.tauCError) ? e : std::max(row.tauCError, e);
            row.error = std::max(row.error, e / q.slab.tauC);
        } else {
            const double e = std::max(std::abs(r.slab.residualDelta - q.slab.residualDelta) /
                                          c.common.slab.limit,
                                      std::abs(r.residualDeltaY - q.residualDeltaY) / c.theta);
            row.residualError = std::isnan(row.residualError) ? e : std::max(row.residualError, e);
            row.error = std::max(row.error, e);
        }
    }
}

// Moreau at h and h/2, Richardson-extrapolated, against the reference's collapse times.
double checkReference(const PlanarPrecisionCase& c, const std::vector<PlanarResult>& ref) {
    double worst = 0.0;
    for (std::size_t k = 0; k < ref.size(); ++k) {
        if (ref[k].slab.outcome != Outcome::Collapsed) continue;
        const SlabModel2D m = planarModel(c.model, c.amplitudes[k], c.fxHz);
        const double horizon = 1.5 * ref[k].slab.tauC;
        const PlanarResult coarse = solveMoreau2D(m, 2.0 * kMoreauStep, horizon);
        const PlanarResult fine = solveMoreau2D(m, kMoreauStep, horizon);
        if (fine.slab.outcome != Outcome::Collapsed || coarse.slab.outcome != Outcome::Collapsed ||
            fine.exitSide != ref[k].exitSide)
            return 1.0;
        const double extrapolated = richardsonFirstOrder(coarse.slab.tauC, fine.slab.tauC);
        worst = std::max(worst, std::abs(extrapolated - ref[k].slab.tauC) / ref[k].slab.tauC);
    }
    return worst;
}
} // namespace

std::vector<PlanarPrecisionCase>
planarPrecisionCases(std::shared_ptr<const Excitation1D> verticalUp) {
    std::vector<PlanarPrecisionCase> cases;
    PlanarCase base; // moderate envelope, mu 0.6, A_y = 0.9 A_x, product normalization
    PlanarCase bench = base;
    bench.fyHz = 1.0;
    cases.push_back({"planar-fy1",
                     "moderate, mu 0.6, f_x = f_y = 1 Hz, A_x 0.9/1.0/1.1 g, gravity only",
                     bench,
                     {0.9, 1.0, 1.1},
                     1.0});
    PlanarCase along = base;
    along.fyHz = 0.2;
    cases.push_back({"planar-along",
                     "f_x 2 Hz, f_y 0.2 Hz, A_x 0.85/0.9/0.95 g: collapses along the walls",
                     along,
                     {0.85, 0.9, 0.95},
                     2.0});
    if (verticalUp) {
        PlanarCase up = bench;
        up.vertical = std::move(verticalUp);
        cases.push_back({"planar-rsn68up",
                         "as planar-fy1 with the RSN68 UP vertical record",
                         up,
                         {0.9, 1.0, 1.1},
                         1.0});
    }
    return cases;
}

std::vector<double> planarPrecisionTolerances() {
    return {1e-4, 1e-6, 1e-8, 1e-10, 1e-12};
}

PlanarPrecisionStudy runPlanarPrecisionStudy(const PlanarPrecisionOptions& options) {
    PlanarPrecisionStudy study;
    study.cases = planarPrecisionCases(options.verticalUp);
    study.moreauStep = kMoreauStep;
    study.reference = "planar solver at rtol 1e-13, atol 1e-15; checked against Moreau's implicit "
                      "Euler at h = 2e-3 and 1e-3 (tau) with Richardson extrapolation";
    const std::vector<double> tols = planarPrecisionTolerances();
    const std::size_t total = study.cases.size() * tols.size();
    for (const PlanarPrecisionCase& c : study.cases) {
        const std::vector<PlanarResult> ref =
            runAll(c, withTolerance(c.model, kRefRelTol, kRefAbsTol));
        study.referenceCheck = std::max(study.referenceCheck, checkReference(c, ref));
        double previousError = std::numeric_limits<double>::quiet_NaN(), previousTol = 0.0;
        for (double tol : tols) {
            const PlanarCase model = withTolerance(c.model, tol, tol / 100.0);
            WorkPrecisionRow row;
            row.caseId = c.id;
            row.solver = "planar";
            char setting[32];
            std::snprintf(setting, sizeof setting, "rtol=%.0e", tol);
            row.setting = setting;
            row.parameter = tol;
            row.points = static_cast<int>(c.amplitudes.size());
            std::vector<PlanarResult> runs;
            row.timing = timeRuns([&] { runs = runAll(c, model); }, options.repeats);
            score(row, runs, ref, c.model);
            for (const PlanarResult& r : runs)
                row.accelEvaluations += r.slab.work.accelEvaluations;
            row.order = previousError > 0.0 && row.error > 0.0
                            ? std::log(previousError / row.error) / std::log(previousTol / tol)
                            : std::numeric_limits<double>::quiet_NaN();
            previousError = row.error;
            previousTol = tol;
            study.rows.push_back(row);
            if (options.onProgress) options.onProgress(study.rows.size(), total);
        }
    }
    return study;
}

std::string planarPrecisionText(const PlanarPrecisionStudy& s) {
    std::ostringstream o;
    o << "\nPlanar cases:\n";
    for (const PlanarPrecisionCase& c : s.cases)
        o << "  " << c.id << ": " << c.description << "\n";
    char line[256];
    std::snprintf(line, sizeof line, "Reference: %s: tau_c within %.1e\n", s.reference.c_str(),
                  s.referenceCheck);
    o << line;
    o << "error as for the 1-DOF study (stable runs: residual dx / limit and dy / theta); order "
         "= d log(error) / d log(rtol)\n\n";
    std::snprintf(line, sizeof line, "%-15s %-11s %5s %7s %9s %9s %6s %10s %10s %9s\n", "case",
                  "setting", "wrong", "events", "tau_c err", "error", "order", "min time s",
                  "median s", "accel");
    o << line;
    for (const WorkPrecisionRow& r : s.rows) {
        std::snprintf(
            line, sizeof line, "%-15s %-11s %5d %7ld %9.2e %9.2e %6.2f %10.3e %10.3e %9ld\n",
            r.caseId.c_str(), r.setting.c_str(), r.outcomeMismatches, r.eventMismatch, r.tauCError,
            r.error, r.order, r.timing.minSeconds, r.timing.medianSeconds, r.accelEvaluations);
        o << line;
    }
    return o.str();
}

} // namespace kinstab
