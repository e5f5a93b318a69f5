// SPDX-License-Identifier: GPL-3.0-or-later
// RecordPreview, continued: its three charts - the ground acceleration, the floor's (or the
// ground's) with the fitted envelope, and the Fourier amplitude spectra - drawn and emptied.

#include "core/excitation/FourierSpectrum.h"
#include "ui/NiceTicks.h"
#include "ui/RecordPreview.h"

#include <QLabel>
#include <QtCharts/QChart>
#include <QtCharts/QLineSeries>
#include <QtCharts/QValueAxis>

#include <algorithm>
#include <cmath>

namespace kinstab::ui {

namespace {

constexpr int kBuckets = 1500;

QValueAxis* axis(QChart* chart, Qt::Orientation o) {
    return qobject_cast<QValueAxis*>(chart->axes(o).value(0));
}

void addSeries(QChart* chart, const QString& name, const QList<QPointF>& points,
               const QColor& color) {
    auto* s = new QLineSeries;
    s->setName(name);
    s->replace(points); // one replace: appending point by point redraws the chart per point
    s->setPen(QPen(color, 1.2));
    chart->addSeries(s);
    s->attachAxis(axis(chart, Qt::Horizontal));
    s->attachAxis(axis(chart, Qt::Vertical));
}

// Round tick values (0, 10, 20 s rather than 0, 10.4, 20.9 s) on the data's own range: ticks at
// the 1-2-5 step nearest to span / count (ui/NiceTicks.h), about `count` of them.
void roundTicks(QValueAxis* a, int count) {
    const double span = a->max() - a->min();
    if (!(span > 0.0)) return;
    const double step = niceTickStep(span, count);
    a->setTickType(QValueAxis::TicksDynamic);
    a->setTickAnchor(0.0);
    a->setTickInterval(step);
    a->setLabelFormat(step >= 1.0 ? "%.0f" : step >= 0.1 ? "%.1f" : "%.2f");
}

void niceAxes(QChart* chart) {
    roundTicks(axis(chart, Qt::Horizontal), 6);
    roundTicks(axis(chart, Qt::Vertical), 4); // the charts are wide and short
}

void clearSeries(QChart* chart) {
    const auto series = chart->series();
    for (QAbstractSeries* s : series) {
        chart->removeSeries(s);
        delete s;
    }
}

} // namespace

void RecordPreview::clear() {
    ground_.reset();
    floor_.reset();
    fit_.reset();
    metrics_.reset();
    error_.clear();
    for (QChart* c : {groundChart(), floorChart(), spectrumChart()})
        clearSeries(c);
    info_->setText(tr("No record."));
    emit recordChanged();
}

void RecordPreview::plotGround() {
    QChart* c = groundChart();
    clearSeries(c);
    addSeries(c, tr("ground"), report::decimatedSeries(ground_->samples, ground_->dt, kBuckets),
              QColor(40, 90, 160));
    const double peak = std::abs(ground_->peak().value);
    axis(c, Qt::Horizontal)->setRange(0.0, ground_->duration());
    axis(c, Qt::Vertical)->setRange(-1.1 * peak, 1.1 * peak);
    niceAxes(c);
    c->legend()->hide();
}

void RecordPreview::plotFloor() {
    QChart* c = floorChart();
    clearSeries(c);
    const Accelerogram& m = floor_ ? *floor_ : *ground_;
    c->setTitle(floor_ ? tr("|Floor acceleration| and fitted envelope (Fig. 27)")
                       : tr("|Ground acceleration| and fitted envelope (floor filter off)"));
    addSeries(c, floor_ ? tr("|floor|") : tr("|ground|"),
              report::decimatedSeries(m.samples, m.dt, kBuckets, true), QColor(120, 120, 120));
    if (fit_) {
        QList<QPointF> env;
        for (int i = 0; i <= 400; ++i) {
            const double t = m.duration() * i / 400.0;
            env.append(QPointF(t, fit_->at(t)));
        }
        addSeries(
            c, tr("envelope α=%1 β=%2 /s").arg(fit_->alpha, 0, 'f', 3).arg(fit_->beta, 0, 'f', 3),
            env, QColor(200, 40, 40));
    }
    axis(c, Qt::Horizontal)->setRange(0.0, m.duration());
    axis(c, Qt::Vertical)->setRange(0.0, 1.1 * std::abs(m.peak().value));
    niceAxes(c);
}

void RecordPreview::plotSpectra() {
    QChart* c = spectrumChart();
    clearSeries(c);
    const double fMax = std::min(15.0, 0.5 / ground_->dt);
    const auto points = [fMax](const AmplitudeSpectrum& s) {
        QList<QPointF> p;
        for (std::size_t k = 0; k < s.frequency.size() && s.frequency[k] <= fMax; ++k)
            p.append(QPointF(s.frequency[k], s.amplitude[k]));
        return p;
    };
    addSeries(c, tr("ground"), points(amplitudeSpectrum(ground_->samples, ground_->dt)),
              QColor(40, 90, 160));
    if (floor_) {
        // Same length as the ground record, so both spectra share their frequency bins.
        const std::vector<double> same(
            floor_->samples.begin(), floor_->samples.begin() + static_cast<long>(ground_->size()));
        addSeries(c, tr("floor"), points(amplitudeSpectrum(same, ground_->dt)),
                  QColor(200, 40, 40));
    }
    axis(c, Qt::Horizontal)->setRange(0.0, fMax);
    axis(c, Qt::Vertical)->setRange(0.0, 1.05);
    niceAxes(c);
}

} // namespace kinstab::ui
