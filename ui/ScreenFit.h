// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A top-level window kept inside the screen it opens on: its frame (title bar and borders, which
// the window manager adds outside the widget) inside QScreen::availableGeometry (the screen less
// panels and docks). A 1280 × 800 window on a 1280 × 800 laptop screen otherwise puts its status
// bar below the screen's edge.

#include <QMargins>
#include <QRect>
#include <QSize>

class QWidget;

namespace kinstab::ui {

// The largest size up to wanted whose window, grown by frame, fits available; never below
// minimum (a window that cannot shrink further is still cut, but by as little as possible).
QSize sizeInside(QSize wanted, const QRect& available, const QMargins& frame, QSize minimum = {});
// The main window's first size on a screen with this available geometry (before any saved
// geometry): 1280 × 800 on a laptop, 85 % of a larger screen (1632 × 918 on 1920 × 1080), so
// that the plots get the room a large screen has; the frame is fitted at the first show.
QSize openingSize(const QRect& available);
// Resizes window (up to wanted) and moves it so that its frame lies inside its screen's
// available geometry. Maximized and full-screen windows are left to the window manager.
void fitToScreen(QWidget* window, QSize wanted);

} // namespace kinstab::ui
