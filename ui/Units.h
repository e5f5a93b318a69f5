// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One unit system for the whole application: SI (m, mm) or US customary (ft, in), chosen in
// View → Units and remembered between sessions. Only what is shown changes: values keep the
// unit they are stored in (a project file names its units: "unit": "ft" | "m" for the building,
// wall_width_in for the wall), so switching never changes a saved project.

#include "core/base/UnitSystem.h"

#include <QString>

namespace kinstab::ui {

using kinstab::LengthScale; // core/base/UnitSystem.h
using kinstab::UnitSystem;

double metresPerDisplayUnit(UnitSystem s, LengthScale scale);
QString lengthSymbol(UnitSystem s, LengthScale scale); // "m", "mm", "ft", "in"
// "SI (m, mm)" / "US customary (ft, in)", for the menu.
QString unitSystemTitle(UnitSystem s);

// The choice kept in QSettings (SI when none was made yet).
UnitSystem savedUnitSystem();
void saveUnitSystem(UnitSystem s);

} // namespace kinstab::ui
