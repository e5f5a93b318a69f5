// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Accelerograms without a standard header (docs/theory.md §7):
//  - values only, any number per line (e.g. BM68elc.acc), with a given dt and unit;
//  - two columns (time, accel) separated by blanks, tabs, ',' or ';', with an optional first
//    line of column names; time must be equally spaced (to 0.1 % of dt), and the record is
//    taken to start at its first row.
// Lines starting with '#' or '%' are comments.

#include "core/records/Accelerogram.h"
#include "core/records/RecordText.h"

namespace kinstab {

Accelerogram parseValues(const RecordText& text, double dt, AccelUnit unit);
Accelerogram parseTimeAccel(const RecordText& text, AccelUnit unit);

} // namespace kinstab
