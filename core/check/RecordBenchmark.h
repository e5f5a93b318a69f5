// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The record path's cost in one process (issue 34), runs alternating so that the machine's drift
// falls on both sides alike: a record run as `simulate --record` computes it (read, floor filter,
// envelope fit, one exact run) against an enveloped-sine run of the same slab; the fit alone
// against that record run (its share); and the record's critical search against the sine's.

#include "core/excitation/RecordExcitation.h"
#include "core/numerics/Timing.h"
#include "core/slab/Slab1DCase.h"
#include "core/sweep/CriticalAmplitude.h"

namespace kinstab {

struct RecordBenchmark {
    double sineAmplitude = 0, sineFrequency = 0; // g, Hz: the sine run's point
    // Per run (a job repeated `sineBatch` times inside one timing is divided back).
    TimingStats recordRun, sineRun;
    double recordOverSine = 0, recordOverSineCpu = 0; // medians of the per-repeat ratios
    TimingStats fit, fitRecordRun;                    // the fit alone, against a record run
    double fitShare = 0, fitShareCpu = 0;             // fit / record run
    TimingStats recordCritical, sineCritical;
    double criticalRatio = 0, criticalRatioCpu = 0; // record search / sine search
    long recordCriticalRuns = 0, sineCriticalRuns = 0;
    int sineBatch = 1;
};

// c: the slab (its envelope drives the sine); the sine runs at (amplitude, frequency) and its
// critical search at frequency. Throws like analyseRecord for an unreadable record.
RecordBenchmark benchmarkRecord(const Slab1DCase& c, const RecordExcitation& record,
                                const CriticalSearch& search, double amplitude, double frequency,
                                int repeats);

} // namespace kinstab
