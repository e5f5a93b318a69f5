// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One unit system for the whole application: SI (m, mm) or US customary (ft, in), chosen in
// View → Units and remembered between sessions. Only what is shown changes: values keep the
// unit they are stored in (a project file names its units: "unit": "ft" | "m" for the building,
// wall_width_in for the wall), so switching never changes a saved project.

#include <QString>

#include <functional>

class QMenu;
class QWidget;

namespace kinstab::ui {

enum class UnitSystem { SI, US };

// Lengths of the building (m | ft) and of details such as a wall's width (mm | in).
enum class LengthScale { Structure, Detail };

double metresPerDisplayUnit(UnitSystem s, LengthScale scale);
QString lengthSymbol(UnitSystem s, LengthScale scale); // "m", "mm", "ft", "in"
// "SI (m, mm)" / "US customary (ft, in)", for the menu.
QString unitSystemName(UnitSystem s);

// The choice kept in QSettings (SI when none was made yet).
UnitSystem savedUnitSystem();
void saveUnitSystem(UnitSystem s);

// Every NumberField below root shows its length in s (fields that are no length ignore it).
void applyUnitSystem(QWidget* root, UnitSystem s);

// View → Units: SI / US customary. Applies the saved choice to root now, and a new choice to
// root, to `also` (views that draw lengths) and to QSettings.
void installUnitsMenu(QMenu* viewMenu, QWidget* root,
                      std::function<void(UnitSystem)> also = nullptr);

} // namespace kinstab::ui
