// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// An entry of a legend drawn as rich text that wraps between entries, never inside one: a
// square in the entry's colour, then its text (HTML). swatchStyle: more CSS for the square
// ("; font-size:large").

#include <QColor>
#include <QString>

namespace kinstab::ui {

inline QString legendEntryHtml(const QColor& colour, const QString& text,
                               const QString& swatchStyle = {}) {
    return QStringLiteral("<span style='white-space:nowrap'><span style='color:%1%2'>&#9632;"
                          "</span> %3</span>")
        .arg(colour.name(), swatchStyle, text);
}

} // namespace kinstab::ui
