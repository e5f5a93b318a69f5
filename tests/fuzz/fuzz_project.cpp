// SPDX-License-Identifier: GPL-3.0-or-later
// Fuzzes the project loader (core/io/Project): any bytes give a project or a ProjectError.
#include "FuzzInput.h"
#include "core/io/Project.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    try {
        kinstab::parseProject(fuzzText(data, size), "/nonexistent-fuzz-dir");
    } catch (const kinstab::ProjectError&) {
    }
    return 0;
}
