// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A small plot of the acceleration envelope e(t), normalized to its peak, with the rise, peak
// and duration times marked: what the chosen preset or alpha/beta means as an earthquake.

#include "core/excitation/Envelope.h"

#include <QChartView>

class QLineSeries;
class QScatterSeries;
class QValueAxis;

namespace kinstab::ui {

class EnvelopeChart : public QChartView {
    Q_OBJECT
public:
    explicit EnvelopeChart(QWidget* parent = nullptr);
    void setEnvelope(const Envelope& e, double tstar);

private:
    QLineSeries* m_curve;
    QScatterSeries* m_marks;
    QValueAxis* m_x;
    QValueAxis* m_y;
};

} // namespace kinstab::ui
