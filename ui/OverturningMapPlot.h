// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The overturning map of a free-standing block (core/rocking/OverturningMap.h) painted as
// Zhang & Makris (2001) draw it: omega_p/p across, a_p/(alpha g) up; a surviving point coloured
// by its largest |theta|/alpha, an overturning one dark. The boundary of the same block under
// the other equations (exact or linearised) is drawn over it, dashed, so the two compare. The
// legend sits to the right of the plot, never over the data. Hovering a point reports it.

#include "core/rocking/OverturningMap.h"

#include <QPen>
#include <QWidget>

#include <optional>

namespace kinstab::ui {

class OverturningMapPlot : public QWidget {
    Q_OBJECT
public:
    explicit OverturningMapPlot(QWidget* parent = nullptr);

    // main: the chosen equations; other: the other equations (same axes), or none.
    void setMaps(const OverturningMap& main, const std::optional<OverturningMap>& other,
                 const QString& mainName, const QString& otherName);
    void clear();
    const OverturningMap& map() const { return m_main; }
    const std::optional<OverturningMap>& otherMap() const { return m_other; }
    // The point under a widget position: (frequency index, amplitude index), or none.
    std::optional<std::pair<int, int>> cellAt(QPointF pos) const;
    QRectF plotRect() const;
    QSize sizeHint() const override { return {640, 480}; }
    QSize minimumSizeHint() const override { return {320, 240}; }

signals:
    void hovered(int frequencyIndex, int amplitudeIndex); // -1, -1: left the plot

protected:
    void paintEvent(QPaintEvent*) override;
    void mouseMoveEvent(QMouseEvent* e) override;
    void leaveEvent(QEvent*) override;

private:
    void rebuildImage();
    void paintBoundary(QPainter& p, const OverturningMap& m, const QPen& pen) const;
    void paintAxes(QPainter& p) const;
    void paintLegend(QPainter& p) const;
    int legendWidth() const;

    OverturningMap m_main;
    std::optional<OverturningMap> m_other;
    QString m_mainName, m_otherName;
    QImage m_cells; // one pixel per point, row 0 the largest amplitude
    int m_hoverI = -1, m_hoverJ = -1;
};

// The colour of a map point: overturns, leaves the base, or survives with max |theta|/alpha.
QColor overturnColor();
QColor leavesBaseColor();
QColor survivesColor(double maxThetaOverAlpha);
QPen otherBoundaryPen(); // the other equations' boundary, dashed

} // namespace kinstab::ui
