// SPDX-License-Identifier: GPL-3.0-or-later
// Fuzzes the friction test CSV reader (core/friction/TripletCsv): any bytes give curves or a
// TripletCsvError.
#include "FuzzInput.h"
#include "core/friction/TripletCsv.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    try {
        kinstab::parseTripletCsv(fuzzText(data, size), "fuzz");
    } catch (const kinstab::TripletCsvError&) {
    }
    return 0;
}
