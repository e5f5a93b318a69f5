// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// PEER strong-motion AT2 files (NGA-West2, older NGA, PEER 2000 and third-party variants;
// data/records/SOURCES.md "Parser notes"): header lines, a line with NPTS and DT in one of
//   "NPTS=   4172, DT=   .0100 SEC, ..."   "NPTS=  4000, DT= .01000 SEC"   "4164  0.0100  NPTS, DT"
// then NPTS values in g, any number per line, blank-separated.

#include "core/records/Accelerogram.h"
#include "core/records/RecordText.h"

namespace kinstab {

Accelerogram parseAt2(const RecordText& text);
Accelerogram readAt2(const std::string& path);

} // namespace kinstab
