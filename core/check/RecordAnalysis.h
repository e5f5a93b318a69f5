// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What a record run gives an engineer (docs/theory.md §7, §9; docs/user-guide.md): the ground
// record and the motion under the slab (through the floor filter when asked), one run of the slab
// under the scaled motion, the critical scale (the smallest peak that collapses the slab) and each
// code's verdict against it. Shared by kinstab-cli (simulate --record, check), the GUI's worker and
// the report.

#include "core/check/RecordCheck.h"
#include "core/excitation/EnvelopeFit.h"
#include "core/excitation/RecordExcitation.h"
#include "core/slab/SlabRecorder.h"
#include "core/sweep/CriticalRecordScale.h"
#include "core/sweep/SweepControl.h"

#include <optional>
#include <vector>

namespace kinstab {

struct RecordAnalysisInput {
    Slab1DCase slab;
    RecordExcitation record;
    CriticalSearch search;
    std::vector<CodeResult> codes; // verdicts for these (none: no verdicts)
    bool critical = true;          // search the critical scale
};

struct RecordAnalysis {
    Accelerogram ground;
    Accelerogram motion;            // under the slab, unscaled
    double peak = 0;                // g, the scaled motion's peak
    double scaleFactor = 1;         // peak / the motion's own peak
    std::optional<EnvelopeFit> fit; // of the motion (Fig. 27); none with fewer than 3 half cycles
    std::string fitError;           // why there is no fit
    std::optional<double> tauRef;   // gamma_c's reference: from the fit, or 1 with TauScale::One
    SlabResult run;
    std::optional<RecordCriticalScale> critical;
    std::vector<CodeVerdict> verdicts;
    bool cancelled = false;
    double runSeconds = 0, criticalSeconds = 0;
};

// Empty when the input can run, else a message naming the field and value.
std::string validateRecordAnalysis(const RecordAnalysisInput& in);
// Throws RecordError for an unreadable file, std::invalid_argument for a bad input.
// control: cancel (the critical search stops within one run) and progress (runs, estimate).
// recorder: what the single run keeps beyond its result (core/slab/SlabRecorder.h: its events,
// for a history); null: nothing. The critical search's runs keep nothing.
RecordAnalysis analyseRecord(const RecordAnalysisInput& in, SweepControl* control = nullptr,
                             SlabRecorder* recorder = nullptr);
// The motion alone (read, filtered), for previews: throws like analyseRecord.
RecordAnalysis recordMotions(const RecordExcitation& record, const Slab1DCase& slab);
// The envelope fitted to a motion (Fig. 27); none, with the reason in *why, when the motion has
// fewer than 3 half cycles.
std::optional<EnvelopeFit> fitOrNone(const Accelerogram& motion, std::string* why = nullptr);
// gamma_c's reference time for a record: tau of the fitted envelope (docs/theory.md §3's tau_rise,
// tau_max, tau_dur computed from alpha, beta), 1 for TauScale::One; none when no fit.
std::optional<double> recordTauRef(const std::optional<EnvelopeFit>& fit, const Slab1DCase& c);

} // namespace kinstab
