// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Text laid out in a width, measured and painted alike. Lines break at word boundaries and,
// where one word alone is wider than the line, inside it: a 200-character name or number
// without a blank (a value a project accepts) would else run out of its box, over its
// neighbours and off the page. "\n" breaks a line.

#include <QFont>
#include <QPaintDevice>
#include <QPainter>
#include <QRectF>
#include <QString>

namespace kinstab::report {

// Height of the text in `width` with the font on the device, as paintWrapped paints it.
double wrappedHeight(const QString& text, const QFont& font, double width, QPaintDevice* device);

// Paints the text into r with the painter's font, wrapped as wrappedHeight measures it.
void paintWrapped(QPainter& p, const QRectF& r, const QString& text,
                  Qt::Alignment align = Qt::AlignLeft);

// The text cut to at most `lines` lines of `width`, its last line ending in "…" when cut: for a
// box of fixed size (the signature block), where a long name must not overrun the lines to sign.
QString elidedToLines(const QString& text, const QFont& font, double width, int lines,
                      QPaintDevice* device);

} // namespace kinstab::report
