// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// `kinstab --screenshot FILE`: run the sweep of the open inputs, pick the paper's Fig. 35 point
// (A = 1.0 g, f = 1.125 Hz, or the nearest grid point), save the window as an image and quit.
// Used for the documentation screenshots, taken from the running app under Xvfb.

#include <QSize>
#include <QString>

namespace kinstab::ui {

class MainWindow;

// size: the window's size for the image (default: the documented 1280×800). gridPoints > 1: the
// sweep runs on that many amplitudes and frequencies over the project's ranges (200: a
// 200×200 grid) instead of the project's steps. tab: the centre tab to show (its title's start;
// empty: the surface). The image is taken once the project's whole assessment is in the
// Verdict panel.
void screenshotAfterSweep(MainWindow& window, const QString& path, QSize size = {1280, 800},
                          int gridPoints = 0, const QString& tab = {});

// `kinstab --screenshot FILE --scenario STEP`: the sweep as above, then one step before the
// image, to show how results follow their inputs (ui/ResultState.h):
//   open:PROJECT  open a second project (every result cleared);
//   codes         a code input only (UBC 1976 zone 4 -> 3): A_crit kept, verdict re-judged;
//   mu            a sweep input (the slab's mu + 0.05): every result dimmed as stale;
//   cancel        a sweep at 10-30 Hz cancelled after 1.5 s: points not computed in grey;
//   top, map      a 200 × 200 sweep shown from straight above / as the 2D map;
//   present       no sweep: the Teaching view in presentation mode (F11), mid-run.
// Any step may end in @WIDTHxHEIGHT for the window size (default 1280x800).
// Returns an error message for an unknown step (empty when it starts).
QString screenshotScenario(MainWindow& window, const QString& step, const QString& path);

} // namespace kinstab::ui
