// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The status bar's run indicator: a bar wide enough for "12 345 / 40 401 steps · 850 /s ·
// about 45 s left" on one line. start() clears the previous run's text before the first poll;
// the total is the one the runner counts, so it agrees with the status line.

#include "ui/TimeLeft.h"

#include <QElapsedTimer>
#include <QProgressBar>

namespace kinstab::ui {

class RunProgress : public QProgressBar {
    Q_OBJECT
public:
    explicit RunProgress(QWidget* parent = nullptr);

    void start(qint64 total, const QString& unit);
    void update(qint64 done, qint64 total);
    void finish();

private:
    QString m_unit;
    TimeLeft m_left;
    QElapsedTimer m_clock;
};

// "about 45 s left", "about 3 min left", "about 1 h 20 min left".
QString timeLeftText(double seconds);

} // namespace kinstab::ui
