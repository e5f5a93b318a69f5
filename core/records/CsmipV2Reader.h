// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// CDMG/CSMIP Volume 2 corrected accelerograms (old upper-case and newer mixed-case "Avol1"
// styles; SOURCES.md §2, §6): one or more channels concatenated, each a text header, integer
// and real header blocks, then accel, veloc and displ blocks
//   "551 POINTS OF ACCEL DATA EQUALLY SPACED AT  .020 SEC.  (UNITS: CM/SEC/SEC)"
//   "7500 points of accel data equally spaced at  .010 sec, in cm/sec2. (8f10.6)"
// in fixed-width fields (8F10.3 unless the line names a format). Only the accel block is read.

#include "core/records/Accelerogram.h"
#include "core/records/RecordText.h"

namespace kinstab {

struct CsmipChannel {
    int number = 0;            // "CHAN 10"
    std::string name;          // "UP"
    std::size_t firstLine = 0; // 0-based line of the channel's first header line
};

std::vector<CsmipChannel> csmipChannels(const RecordText& text);
// channel: the channel number ("10") or its name ("UP", any case); empty = the first channel.
Accelerogram parseCsmipV2(const RecordText& text, const std::string& channel = {});
Accelerogram readCsmipV2(const std::string& path, const std::string& channel = {});

} // namespace kinstab
