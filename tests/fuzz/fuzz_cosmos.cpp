// SPDX-License-Identifier: GPL-3.0-or-later
// Fuzzes core/io/CosmosReader: any bytes give a record or a RecordError.
#include "FuzzInput.h"
#include "core/records/CosmosReader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    try {
        kinstab::parseCosmos(kinstab::RecordText(fuzzText(data, size), "fuzz"));
    } catch (const kinstab::RecordError&) {
    }
    return 0;
}
