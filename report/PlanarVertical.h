// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The vertical motion a planar project names (core/slab/PlanarSettings.h), read for a run, and its
// words for labels and the report. The reading is core's (core/slab/VerticalRecord.h: the shipped
// RSN68 UP compiled into the program, or a record file), so the main window's sweeps, the design
// report and kinstab-cli's compute commands all run the same case.

#include "core/records/Accelerogram.h"
#include "core/slab/PlanarSettings.h"

#include <QString>

#include <optional>

namespace kinstab::ui {

// The shipped stand-in for the paper's Pacoima Dam vertical (a built-in resource), and the note
// every label and the report show with it.
QString defaultVerticalRecordPath();
QString defaultVerticalRecordNote();

// nullopt for "none". Throws InputError "planar.vertical = 'PATH': reason" when it cannot be read.
std::optional<Accelerogram> readVerticalRecord(const PlanarSettings& s);

// The planar case of a project's 1-DOF case and settings, with its vertical record loaded.
// Throws InputError naming the field.
PlanarCase projectPlanarCase(const Slab1DCase& common, const PlanarSettings& s);

// One line for labels and the report: "none (gravity only)", "RSN68 UP ... stands in for ...",
// or the record file's name.
QString verticalDescription(const PlanarSettings& s);
// Short model description: "planar (f_y = 1 Hz, A_y/A_x = 0.9, Θ = 20, vertical RSN68 UP)".
QString planarSummary(const PlanarSettings& s);

} // namespace kinstab::ui
