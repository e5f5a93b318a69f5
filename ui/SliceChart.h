// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// γc and τc against amplitude A at one frequency (the paper's Fig. 34): how steeply the
// collapse factor rises past the critical amplitude.

#include <QChartView>

#include <vector>

class QLineSeries;
class QScatterSeries;
class QValueAxis;

namespace kinstab::ui {

class SliceChart : public QChartView {
    Q_OBJECT
public:
    explicit SliceChart(QWidget* parent = nullptr);
    // tauC is NaN where the slab did not collapse (or the point is not computed).
    void setSlice(double frequency, const std::vector<double>& amplitudes,
                  const std::vector<double>& gamma, const std::vector<double>& tauC,
                  const QString& gammaTitle);
    void clearSlice();

private:
    QLineSeries* m_gamma;
    QScatterSeries* m_tau;
    QValueAxis* m_x;
    QValueAxis* m_yGamma;
    QValueAxis* m_yTau;
};

} // namespace kinstab::ui
