// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/teaching/TextScale.h"

#include <QGuiApplication>
#include <QPainter>

#include <algorithm>
#include <cmath>

namespace kinstab::ui {

double textScale(const QPainter& p) {
    return textScale(p.font());
}

double textScale(const QFont& font) {
    const double base = QGuiApplication::font().pointSizeF();
    const double now = font.pointSizeF();
    if (!(base > 0) || !(now > 0)) return 1.0; // a pixel-sized font: no scale known
    return std::clamp(now / base, 0.5, 4.0);
}

int scaledPixels(const QPainter& p, double pixels, double maxScale) {
    return scaledPixels(p.font(), pixels, maxScale);
}

int scaledPixels(const QFont& font, double pixels, double maxScale) {
    return static_cast<int>(std::lround(pixels * std::min(textScale(font), maxScale)));
}

} // namespace kinstab::ui
