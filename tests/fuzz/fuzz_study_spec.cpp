// SPDX-License-Identifier: GPL-3.0-or-later
// Fuzzes the study spec reader (core/io/StudySpecJson): any bytes give a spec or a StudyError.
#include "FuzzInput.h"
#include "core/io/StudySpecJson.h"
#include "core/study/StudySpec.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    try {
        kinstab::studyFromJsonText(fuzzText(data, size), "/nonexistent-fuzz-dir");
    } catch (const kinstab::StudyError&) {
    }
    return 0;
}
