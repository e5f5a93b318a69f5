// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/teaching/SidePanel.h"

#include "ui/Scrollable.h"

#include <QComboBox>
#include <QLabel>
#include <QScrollArea>
#include <QVBoxLayout>

namespace kinstab::ui {

SideColumn sideColumn() {
    SideColumn c;
    c.widget = new QWidget;
    c.layout = new QVBoxLayout(c.widget);
    c.layout->setContentsMargins(0, 0, 0, 0);
    return c;
}

QComboBox* presetBox(QWidget* parent, const QString& toolTip) {
    auto* box = new QComboBox(parent);
    box->setToolTip(toolTip);
    box->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    box->setMinimumContentsLength(10);
    return box;
}

QLabel* captionLabel(QWidget* parent) {
    auto* label = new QLabel(parent);
    label->setWordWrap(true);
    label->setStyleSheet(QStringLiteral("color: #555;"));
    return label;
}

QLabel* outcomeLabel(QWidget* parent) {
    auto* label = new QLabel(parent);
    label->setWordWrap(true);
    label->setTextFormat(Qt::RichText);
    return label;
}

QWidget* sideScroll(QWidget* column) {
    auto* scroll = static_cast<QScrollArea*>(scrollable(column));
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    scroll->setFixedWidth(350);
    return scroll;
}

} // namespace kinstab::ui
