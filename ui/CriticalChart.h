// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The critical amplitude A_crit(f) — below it the slab does not fall — with each code's
// top-floor ratio as a horizontal line and the building's frequency as a vertical one. A code
// line below the curve at the building's f means overstress governs.

#include "ui/SurfaceData.h"

#include <QChartView>

class QLineSeries;
class QValueAxis;

namespace kinstab::ui {

class CriticalChart : public QChartView {
    Q_OBJECT
public:
    explicit CriticalChart(QWidget* parent = nullptr);
    void setData(const SurfaceOverlays& o, double fMin, double fMax);

private:
    QLineSeries* m_curve;
    std::vector<QLineSeries*> m_lines;
    QValueAxis* m_x;
    QValueAxis* m_y;
};

} // namespace kinstab::ui
