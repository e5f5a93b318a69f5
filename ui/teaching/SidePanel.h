// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The parts both teaching views' side panels (TeachingView, BlockTeachingView) are made of: a
// margin-free column that scrolls on its own at a fixed width, a preset box, the preset's grey
// caption and the run's outcome line. Each view fills in its own presets, tooltips and rows.

class QComboBox;
class QLabel;
class QString;
class QVBoxLayout;
class QWidget;

namespace kinstab::ui {

struct SideColumn {
    QWidget* widget = nullptr;
    QVBoxLayout* layout = nullptr; // no margins
};

SideColumn sideColumn();
// A preset box that stays narrow however long its entries (10 characters shown).
QComboBox* presetBox(QWidget* parent, const QString& toolTip);
// The preset's caption: wrapped, grey.
QLabel* captionLabel(QWidget* parent);
// The run's outcome: wrapped rich text.
QLabel* outcomeLabel(QWidget* parent);
// The column in a frameless scroll area (ui/Scrollable.h) 350 px wide, scrolling only vertically:
// a taller panel (more fields, large text) must not push the play bar below the window. The view
// puts it in its layout.
QWidget* sideScroll(QWidget* column);

} // namespace kinstab::ui
