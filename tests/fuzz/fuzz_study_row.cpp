// SPDX-License-Identifier: GPL-3.0-or-later
// Fuzzes the study results' row parser (core/io/StudyRowJson): each line of any bytes gives a row
// or a StudyRowError naming what is wrong.
#include "FuzzInput.h"
#include "core/io/StudyRowJson.h"

#include <sstream>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::istringstream lines(fuzzText(data, size));
    std::string line;
    for (int n = 0; n < 64 && std::getline(lines, line); ++n) {
        try {
            kinstab::parseStudyRow(line);
        } catch (const kinstab::StudyRowError&) {
        }
    }
    return 0;
}
