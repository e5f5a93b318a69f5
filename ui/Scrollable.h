// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A panel in a frameless scroll area that resizes it: the panel's minimum size must not grow
// the window past 1280×800 (the main window's tabs and docks).

class QWidget;

namespace kinstab::ui {

QWidget* scrollable(QWidget* w);

} // namespace kinstab::ui
