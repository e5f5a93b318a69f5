// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The a(tau) and delta(tau) traces with the cursor (painted by paintTraces). Click or drag to
// scrub.

#include "ui/teaching/TeachingRun.h"

#include <QWidget>

namespace kinstab::ui {

class TracePlot : public QWidget {
    Q_OBJECT
public:
    explicit TracePlot(QWidget* parent = nullptr);
    // The run must outlive its display here (TeachingView owns it).
    void setRun(const TeachingRun* run);
    void setCursor(double tau);
    double cursorTau() const { return cursor_; }
    QSize sizeHint() const override { return {760, 300}; }
    // Two strips of 60-odd px each: what the Teaching tab at 1280 × 800 leaves them.
    QSize minimumSizeHint() const override { return {360, 150}; }

signals:
    void seekRequested(double tau);

protected:
    void paintEvent(QPaintEvent*) override;
    void mousePressEvent(QMouseEvent* e) override;
    void mouseMoveEvent(QMouseEvent* e) override;

private:
    const TeachingRun* run_ = nullptr;
    double cursor_ = 0;
};

} // namespace kinstab::ui
