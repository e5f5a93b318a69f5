// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The vertical motion a planar project names (core/slab/PlanarSettings.h), read for a run without
// Qt: the shipped RSN68 UP from the text compiled into the program (core/records/ShippedRecords.h),
// or a record file. kinstab-cli, the GUI and the report all call it, so every front end runs the
// same case.

#include "core/records/Accelerogram.h"
#include "core/records/ShippedRecords.h"
#include "core/slab/PlanarSettings.h"

#include <optional>
#include <string>

namespace kinstab {

// nullopt for "none". Throws InputError "planar.vertical = 'PATH': reason" when it cannot be read.
std::optional<Accelerogram> loadVerticalRecord(const PlanarSettings& s);

// The planar case of a project's 1-DOF case and settings, with its vertical record loaded.
// Throws InputError naming the field.
PlanarCase planarCaseWithVertical(const Slab1DCase& common, const PlanarSettings& s);

} // namespace kinstab
