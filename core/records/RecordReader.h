// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One entry point for every accelerogram format (docs/theory.md §7): picks the reader by the file's
// first lines unless told, and validates the result.

#include "core/records/Accelerogram.h"
#include "core/records/RecordText.h"

#include <optional>
#include <string>

namespace kinstab {

enum class RecordFormat { Auto, At2, Cosmos, CsmipV2, Values, TimeAccel };
std::string
recordFormatName(RecordFormat f); // "auto", "at2", "cosmos", "csmip", "values", "time-accel"
std::optional<RecordFormat> recordFormatFromName(const std::string& name);

struct RecordReadOptions {
    RecordFormat format = RecordFormat::Auto;
    std::optional<double> dt;      // s: needed by a file of values only
    std::optional<AccelUnit> unit; // for headerless files (default g); headers name their own
    std::string channel;           // CSMIP V2: channel number or name; empty = first
};

// Auto: COSMOS ("(Format v.. with N text lines)"), CSMIP V2 ("CORRECTED ACCELEROGRAM"),
// AT2 (an NPTS line in the first lines), else values when dt is given, else time-accel.
RecordFormat detectRecordFormat(const RecordText& text, const RecordReadOptions& options);
Accelerogram parseRecord(const RecordText& text, const RecordReadOptions& options = {});
// Throws RecordError ("FILE:LINE: message") for a missing, empty or broken file.
Accelerogram readRecord(const std::string& path, const RecordReadOptions& options = {});

} // namespace kinstab
