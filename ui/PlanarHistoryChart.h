// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The history of one picked point of a planar surface: δx (across the walls, collapse at
// ±limit) and δy (along them, collapse at ±Θ) against τ, on their own axes because Θ is
// usually many times the limit.

#include "ui/PlanarPointRun.h"

#include <QChartView>

class QLineSeries;
class QValueAxis;

namespace kinstab::ui {

class PlanarHistoryChart : public QChartView {
    Q_OBJECT
public:
    explicit PlanarHistoryChart(QWidget* parent = nullptr);
    void setRun(const PlanarPointRun& run);
    void clearRun();         // no picked point (New/Open)
    int sampleCount() const; // points in the δx series (tests)

private:
    QLineSeries* m_dx;
    QLineSeries* m_dy;
    QLineSeries* m_limitUp;
    QLineSeries* m_limitDown;
    QValueAxis* m_x;
    QValueAxis* m_yx;
    QValueAxis* m_yy;
};

} // namespace kinstab::ui
