// SPDX-License-Identifier: GPL-3.0-or-later
// Fuzzes core/io/At2Reader: any bytes give a record or a RecordError.
#include "FuzzInput.h"
#include "core/records/At2Reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    try {
        kinstab::parseAt2(kinstab::RecordText(fuzzText(data, size), "fuzz"));
    } catch (const kinstab::RecordError&) {
    }
    return 0;
}
