// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Text in the painted teaching scene follows the view's font scale (presentation mode): the
// painter starts with the widget's font, so its size against the application font is the scale.

class QFont;
class QPainter;

namespace kinstab::ui {

// 1 for normal text, 2 when the view's font is twice the application's (clamped to [0.5, 4]).
double textScale(const QPainter& p);
double textScale(const QFont& font); // the same for a widget's font, outside painting
// A pixel size given for normal text, scaled, at most by maxScale: labels placed inside a
// drawing (axes, dimensions) have fixed room and take less of the scale than headings.
int scaledPixels(const QPainter& p, double pixels, double maxScale = 4.0);
int scaledPixels(const QFont& font, double pixels, double maxScale = 4.0);
inline constexpr double kLabelMaxScale = 1.5;

} // namespace kinstab::ui
