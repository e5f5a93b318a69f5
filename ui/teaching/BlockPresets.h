// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One-click cases of the rocking literature for the block animation, each as its paper states
// it (the numbers are those core's tests check: tests/core/tst_rocking_free.cpp,
// tst_rocking_pulses.cpp):
//   Housner (1963): free rocking released from theta0 = alpha/2;
//   Makris & Roussos (2000): their worked example, b = 0.2 m, h = 0.6 m, a half-sine of 1 Hz and
//     5.44 m/s^2 (just above eq. 27's 5.439 m/s^2) overturns the block;
//   Zhang & Makris (2001): p = 2.14 rad/s, alpha = 0.25, eta = 0.9, one-sine at omega_p/p = 5:
//     4.5 alpha g overturns after an impact, 7.0 alpha g survives (the safe cape);
//   Housner (1963) eq. 9: a rectangular pulse of 2 alpha g just longer than
//     cosh(p t1) = 1 + 1/(2 psi (psi - 1)) overturns the block;
//   a squat block with mu below tan alpha slides instead of rocking (Shenton 1996).

#include "ui/teaching/BlockRun.h"

#include <QString>

#include <vector>

namespace kinstab::ui {

struct BlockPreset {
    QString id;      // "housner-free"
    QString title;   // what happens, in plain words
    QString source;  // "Housner 1963"
    QString caption; // what to watch for, with the paper's numbers
    BlockCase blockCase;
};

const std::vector<BlockPreset>& blockPresets();
const BlockPreset* findBlockPreset(const QString& id);

} // namespace kinstab::ui
