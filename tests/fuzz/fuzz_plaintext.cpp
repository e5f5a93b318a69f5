// SPDX-License-Identifier: GPL-3.0-or-later
// Fuzzes core/io/PlainTextReader (a column of values, and time-acceleration pairs) and the
// format detection in front of it: any bytes give a record or a RecordError.
#include "FuzzInput.h"
#include "core/records/PlainTextReader.h"
#include "core/records/RecordReader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace kinstab;
    const RecordText text(fuzzText(data, size), "fuzz");
    try {
        parseValues(text, 0.01, AccelUnit::G);
    } catch (const RecordError&) {
    }
    try {
        parseTimeAccel(text, AccelUnit::G);
    } catch (const RecordError&) {
    }
    try {
        parseRecord(text); // auto-detection, then whichever reader it picks
    } catch (const RecordError&) {
    }
    return 0;
}
