// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// COSMOS strong-motion format, volumes 1 and 2 (".V1", ".V2", ".V1c", ".V2c"; COSMOS format
// v01.20): text header ("with 13 text lines"), integer and real header blocks, comment lines
// starting with '|', then "N acceleration pts, ..., units=cm/sec2(04),Format=(1E15.6)" and the
// values. The sample interval is real header #62, in milliseconds (SOURCES.md §6; #34 is the
// raw sampling interval, not the processed one).

#include "core/records/Accelerogram.h"
#include "core/records/RecordText.h"

namespace kinstab {

Accelerogram parseCosmos(const RecordText& text);
Accelerogram readCosmos(const std::string& path);

} // namespace kinstab
