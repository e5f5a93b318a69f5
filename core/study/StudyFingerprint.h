// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The identity of a study, written in every row (docs/studies.md, "study"): a hash of what
// decides its rows - the parameter lists, the building, the intensity measure, the search and,
// per record, its scale and the SHA-256 of its file's bytes. Shards of two studies differ in it
// even when their case counts agree, so merge, fragility, the report and the Study tab refuse
// to take one study's rows for another's, and study --resume continues only its own rows.
// Left out, because they do not change a row's numbers: the study's name, where the records
// are (a shard may run on a machine that mounts them elsewhere) and the study file's layout.

#include "core/study/StudySpec.h"

#include <cstddef>
#include <string>
#include <string_view>

namespace kinstab {

// 16 hex digits (64 bits): two different studies share one with probability 2^-64.
inline constexpr std::size_t kStudyFingerprintDigits = 16;

// Throws std::logic_error when a record has not been read yet (core/study/StudyRecords.h).
std::string studyFingerprint(const StudySpec& s);
bool isStudyFingerprint(std::string_view text); // kStudyFingerprintDigits lowercase hex digits

} // namespace kinstab
