// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The shipped sample records (resources/records, provenance in its SOURCES.md) as the core
// tests drive slabs with them: the ground motion, or the floor motion through the 2 % floor
// filter of period T (docs/theory.md §7).

#include "core/excitation/FloorFilter.h"
#include "core/records/RecordReader.h"

#include <string>

namespace kinstab::testing {

inline const std::string kRecords = KINSTAB_SOURCE_DIR "/resources/records/";

// floorPeriod <= 0: the ground motion itself.
inline Accelerogram motionOf(const std::string& file, double floorPeriod) {
    const Accelerogram ground = readRecord(kRecords + file);
    if (floorPeriod <= 0.0) return ground;
    return floorMotion(ground, FloorFilterParams{floorPeriod, 0.02, std::nullopt});
}

} // namespace kinstab::testing
