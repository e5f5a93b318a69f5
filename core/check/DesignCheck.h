// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The design check of the paper's chapter V: for each code, compare the top-floor ratio
// F_top / w_top with the critical amplitude A_crit(f) of the 1-DOF slab at the building's
// frequency f = 1/T. Below A_crit the members overstress first; at or above it the slab can
// slide off (kinetic instability). Margin = A_crit / ratio.

#include "core/codes/CodeResult.h"
#include "core/codes/Verdict.h"
#include "core/slab/Slab1DCase.h"
#include "core/sweep/CriticalAmplitude.h"

#include <optional>
#include <string>
#include <vector>

namespace kinstab {

struct CodeVerdict {
    std::string code;
    std::string title;
    double ratio = 0;                     // F_top / w_top as the code requires it
    std::optional<double> ratioWithoutFt; // UBC: the paper's figure
    double periodSeconds = 0;
    double frequencyHz = 0;       // 1 / T
    std::optional<double> aCrit;  // nullopt: nothing collapses up to the search limit
    std::optional<double> margin; // A_crit / ratio; nullopt when aCrit or ratio is absent
    Verdict verdict = Verdict::OverstressGoverns;
    std::string explanation;
};

struct DesignCheckResult {
    std::vector<CodeVerdict> codes;
    long runs = 0; // slab runs spent on the A_crit searches
};

// A_crit(f) is searched once per distinct frequency. Throws InputError on a bad case or search.
DesignCheckResult designCheck(const std::vector<CodeResult>& codes, const Slab1DCase& slab,
                              const CriticalSearch& search = {});
// The same with the slab runs supplied by the caller: the GUI passes one that returns at once
// after a cancel, so a running check stops within one run. scanFrom: where the A_crit scan
// starts, below which nothing slips (default the slab's mu; the planar model passes
// planarNoSlipAmplitude, and `point` runs that model).
DesignCheckResult designCheck(const std::vector<CodeResult>& codes, const Slab1DCase& slab,
                              const CriticalSearch& search, const PointFunction& point,
                              std::optional<double> scanFrom = std::nullopt);

// Empty when fine, else the message naming the field as `prefix` + from | max_amplitude |
// scan_step | tolerance ("check." in a project; "" names Python's keywords).
std::string validateCriticalSearch(const CriticalSearch& s, const std::string& prefix = "check.");

// One code's verdict against a critical amplitude (nullopt: nothing collapsed up to
// searchLimit); shared by the sine's check and the record's (core/check/RecordCheck.h).
CodeVerdict judgeCode(const CodeResult& r, std::optional<double> aCrit, double searchLimit);

} // namespace kinstab
