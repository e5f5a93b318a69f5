// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The history of one picked point (the paper's Fig. 35): relative displacement δ(τ), the floor
// acceleration a(τ) inside its envelope, the ±μ slip thresholds, and the slip intervals shaded.

#include "ui/PointRun.h"

#include <QChartView>

class QAreaSeries;
class QLineSeries;
class QValueAxis;

namespace kinstab::ui {

class HistoryChart : public QChartView {
    Q_OBJECT
public:
    explicit HistoryChart(QWidget* parent = nullptr);
    void setRun(const PointRun& run);
    void clearRun();         // no picked point (New/Open)
    int sampleCount() const; // points in the δ(τ) series (tests)

private:
    QLineSeries* m_delta;
    QLineSeries* m_accel;
    QLineSeries* m_envUp;
    QLineSeries* m_envDown;
    QLineSeries* m_muUp;
    QLineSeries* m_muDown;
    QLineSeries* m_slipTop;
    QLineSeries* m_slipBase;
    QAreaSeries* m_slip;
    QValueAxis* m_x;
    QValueAxis* m_yDelta;
    QValueAxis* m_yAccel;
};

} // namespace kinstab::ui
