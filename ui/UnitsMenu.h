// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// View → Units and what it changes: the menu's two choices, and every NumberField of a window
// shown in the chosen system (ui/Units.h holds the systems, their symbols and the saved choice).

#include "ui/Units.h"

#include <functional>

class QMenu;
class QWidget;

namespace kinstab::ui {

// The menu's check mark follows s (a project opened in its own units), without saving it as
// the user's choice.
void showUnitSystem(QWidget* root, UnitSystem s);

// Every NumberField below root shows its length in s (fields that are no length ignore it).
void applyUnitSystem(QWidget* root, UnitSystem s);

// View → Units: SI / US customary. Applies the saved choice to root now, and a new choice to
// root, to `also` (views that draw lengths) and to QSettings.
void installUnitsMenu(QMenu* viewMenu, QWidget* root,
                      std::function<void(UnitSystem)> also = nullptr);

} // namespace kinstab::ui
