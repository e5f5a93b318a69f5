// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The vertical motion a planar project names (core/slab/PlanarSettings.h), read for a run, and its
// words for labels and the report. The reading is core's (core/slab/VerticalRecord.h: the shipped
// RSN68 UP compiled into the program, or a record file), so the main window's sweeps, the design
// report and kinstab-cli's compute commands all run the same case.

#include "core/slab/PlanarSettings.h"

#include <QString>

namespace kinstab::report {

// The shipped stand-in for the paper's Pacoima Dam vertical (a built-in resource), and the note
// every label and the report show with it.
QString defaultVerticalRecordPath();
QString defaultVerticalRecordNote();

// One line for labels and the report: "none (gravity only)", "RSN68 UP ... stands in for ...",
// or the record file's name.
QString verticalDescription(const PlanarSettings& s);

} // namespace kinstab::report
