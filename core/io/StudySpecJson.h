// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Reads a study file: versioned JSON ({"format": "kinstab-study", "version": 1, ...}), every bad
// field a StudyError naming it ("parameters.mu[2] = -1: must be > 0"); folders of records are
// expanded in name order.

#include "core/study/StudySpec.h"

#include <string>

namespace kinstab {

// Throws StudyError naming the field; baseDir resolves relative record paths.
StudySpec studyFromJsonText(const std::string& text, const std::string& baseDir);
StudySpec loadStudy(const std::string& path); // throws StudyError

} // namespace kinstab
