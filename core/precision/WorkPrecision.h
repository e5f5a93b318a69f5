// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Work-precision study (docs/theory.md §6.6; docs/theory.md §6.7): for a fixed, documented set of
// cases, the error of each solver and setting against a converged reference, and its wall time.
//  - paper RK4 at H = T/16 ... T/1024;
//  - the exact solver with its stop/collapse times located to 1e-2 ... 1e-12 (absolute, tau);
//  - tanh-regularized friction with RK4 at widths (1e-1, 1e-2, 1e-3) mu/omega.
// Reference: the exact solver's event sequence (events located to a few ulps) replayed in long
// double by LongDoubleReplay.h, which solves every event time again in extended precision; it
// shares the order of events with the solver, not its arithmetic.
// The GUI's Numerics view plots error against wall time (log-log) from WorkPrecisionStudy.

#include "core/numerics/Timing.h"
#include "core/slab/Slab1DCase.h"

#include <functional>
#include <string>
#include <vector>

namespace kinstab {

struct WorkPrecisionCase {
    std::string id;
    std::string description;
    Slab1DCase model;               // solver field unused
    std::vector<double> amplitudes; // g; every amplitude is one run of the case
    double frequencyHz = 1.0;
};

// The fixed case set: paper grid at 1 Hz, grazing, chattering, high frequency, long duration.
std::vector<WorkPrecisionCase> workPrecisionCases();

struct WorkPrecisionRow {
    std::string caseId;
    std::string solver;   // "paper", "exact", "regularized"
    std::string setting;  // e.g. "H=T/64", "tol=1e-08", "eps=1e-02 mu/omega"
    double parameter = 0; // H, tolerance or width, for the observed order
    int points = 0;
    int outcomeMismatches = 0; // runs whose outcome differs from the reference
    long eventMismatch = -1;   // sum over runs of |events - reference events|; -1: not defined
    double tauCError = 0;      // max |tau_c - ref| over runs collapsed in both (NaN: none)
    double residualError = 0;  // max |residual delta - ref| over runs stable in both (NaN: none)
    // Max over runs of: |tau_c - ref| / ref (collapsed), |delta - ref| / limit (stable), and
    // 1 for a run whose outcome is wrong. The error axis of the plot.
    double error = 0;
    double order = 0; // log(error ratio) / log(parameter ratio) against the previous row; NaN
    TimingStats timing;
    long accelEvaluations = 0; // per pass over the case's runs
};

struct WorkPrecisionStudy {
    std::vector<WorkPrecisionCase> cases;
    std::vector<WorkPrecisionRow> rows;
    std::string reference; // how the reference is made
    double referenceConvergence =
        0;                  // max |ref - exact at tolerance 0| over all runs (tau_c, delta)
    bool cancelled = false; // stopped early: rows holds only the settings finished
};

struct WorkPrecisionOptions {
    int repeats = 5; // timed runs after a warm-up (3 for settings slower than 0.5 s a run)
    bool includeRegularized = true;
    // Called after each row with (rows done, rows total); may be empty.
    std::function<void(std::size_t, std::size_t)> onProgress;
    // Asked before each row; true stops the study there (a row takes up to a few seconds).
    std::function<bool()> cancelled;
};

WorkPrecisionStudy runWorkPrecisionStudy(const WorkPrecisionOptions& options = {});

std::string workPrecisionCsv(const WorkPrecisionStudy& s);
std::string workPrecisionText(const WorkPrecisionStudy& s); // the printed table

} // namespace kinstab
