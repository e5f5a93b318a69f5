// SPDX-License-Identifier: GPL-3.0-or-later
// Fuzzes the hazard readers (core/risk/HazardFile.h): any bytes, in each format and detected,
// give a curve or a HazardError.
#include "FuzzInput.h"
#include "core/risk/HazardFile.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text = fuzzText(data, size);
    for (const kinstab::HazardFormat f :
         {kinstab::HazardFormat::Auto, kinstab::HazardFormat::OpenQuake,
          kinstab::HazardFormat::Usgs, kinstab::HazardFormat::Csv}) {
        try {
            kinstab::parseHazardText(text, "fuzz", {f, std::nullopt, std::nullopt});
        } catch (const kinstab::HazardError&) {
        }
    }
    return 0;
}
