// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/ScreenFit.h"

#include <QScreen>
#include <QWidget>
#include <QWindow>

#include <algorithm>

namespace kinstab::ui {

QSize sizeInside(QSize wanted, const QRect& available, const QMargins& frame, QSize minimum) {
    const int w = available.width() - frame.left() - frame.right();
    const int h = available.height() - frame.top() - frame.bottom();
    return {std::max(std::min(wanted.width(), w), minimum.width()),
            std::max(std::min(wanted.height(), h), minimum.height())};
}

QSize openingSize(const QRect& available) {
    constexpr double kShare = 0.85;
    const QSize share(static_cast<int>(available.width() * kShare),
                      static_cast<int>(available.height() * kShare));
    return sizeInside(share.expandedTo({1280, 800}), available, {});
}

void fitToScreen(QWidget* window, QSize wanted) {
    if (!window || window->isMaximized() || window->isFullScreen()) return;
    const QScreen* screen = window->screen();
    if (!screen) return;
    const QRect available = screen->availableGeometry();
    // Known once the platform window exists; zero before, and on X11 until the window manager
    // has framed the window (the caller fits again then).
    const QMargins frame =
        window->windowHandle() ? window->windowHandle()->frameMargins() : QMargins();
    const QSize size = sizeInside(wanted, available, frame, window->minimumSize());
    if (size != window->size()) window->resize(size);
    // The frame's top-left, moved only as far as needed to bring the frame inside.
    const QSize outer = size.grownBy(frame);
    const QPoint at = window->frameGeometry().topLeft();
    const QPoint inside(
        std::clamp(at.x(), available.left(),
                   std::max(available.left(), available.right() + 1 - outer.width())),
        std::clamp(at.y(), available.top(),
                   std::max(available.top(), available.bottom() + 1 - outer.height())));
    if (inside != at) window->move(inside); // a top-level's pos() is its frame's
}

} // namespace kinstab::ui
