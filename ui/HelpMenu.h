// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The Help menu of the main window: User guide (F1: the section of the panel in focus) and
// About. One call from the window that owns the menu bar.

#include <QString>

class QMainWindow;
class QWidget;

namespace kinstab::ui {

// Adds Help → User guide (F1) and Help → About to window's menu bar.
void installHelpMenu(QMainWindow* window);
// The user-guide section for a widget: that of the dock or central tab holding it, or the
// five-step introduction when it is in neither.
QString helpSectionFor(const QWidget* focus);
// Opens (or raises) window's help window at section; returns it.
QWidget* showUserGuide(QMainWindow* window, const QString& section);

} // namespace kinstab::ui
