// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The design check with a record (docs/theory.md §9 with §7): each code's top-floor ratio against
// the critical peak of the scaled record (core/sweep/CriticalRecordScale.h) instead of A_crit(f) of
// the enveloped sine. A record carries its own frequency content, so one critical peak serves
// every code; the verdict rule is the sine's (judgeCode).

#include "core/check/DesignCheck.h"
#include "core/sweep/CriticalRecordScale.h"

#include <vector>

namespace kinstab {

std::vector<CodeVerdict> recordVerdicts(const std::vector<CodeResult>& codes,
                                        const RecordCriticalScale& critical,
                                        const CriticalSearch& search);

} // namespace kinstab
