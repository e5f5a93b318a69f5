// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/RecordMetricsText.h"

#include <QCoreApplication>

namespace kinstab::ui {

namespace {

QString tr(const char* text) {
    return QCoreApplication::translate("RecordMetrics", text);
}

// Three significant digits: the records' own precision, not the double's.
QString num(double x) {
    return QString::number(x, 'g', 3);
}

QString num(const std::optional<double>& x) {
    return x ? num(*x) : QStringLiteral("–");
}

QString saLabel(const RecordMetrics& m) {
    return m.sa ? tr("Sa(%1 s, %2 %)").arg(num(m.sa->period)).arg(100.0 * m.sa->damping) : tr("Sa");
}

} // namespace

QString recordMetricsLine(const RecordMetrics& m) {
    QString s = tr("PGA %1 g · PGV %2 cm/s · PGD %3 cm · Arias %4 m/s · D5–95 %5 s · Tm %6 s")
                    .arg(num(m.pga), num(100.0 * m.pgv), num(100.0 * m.pgd), num(m.arias),
                         num(m.d5_95), num(m.meanPeriod));
    if (m.sa) s += tr(" · %1 %2 g").arg(saLabel(m), num(m.sa->g));
    return s;
}

QStringList recordMetricsHeaders() {
    return {tr("PGA g"),   tr("PGV cm/s"), tr("PGD cm"), tr("Arias m/s"),
            tr("D5–95 s"), tr("Tm s"),     tr("Sa(T) g")};
}

QStringList recordMetricsCells(const RecordMetrics& m) {
    return {num(m.pga),
            num(100.0 * m.pgv),
            num(100.0 * m.pgd),
            num(m.arias),
            num(m.d5_95),
            num(m.meanPeriod),
            m.sa ? num(m.sa->g) : QStringLiteral("–")};
}

QString recordMetricsToolTip() {
    return tr("Computed when the record is read: PGA, PGV and PGD (velocity and displacement "
              "integrated exactly for the linear-between-samples record from rest, no baseline "
              "correction), Arias intensity π/(2g)∫a²dt, significant duration D5–95 (5 % to "
              "95 % of the Arias integral), mean period Tm (Rathje et al. 1998, 0.25–20 Hz) "
              "and Sa(T, 5 %), the peak absolute acceleration of a 5 %-damped oscillator of "
              "the building's period T (Nigam–Jennings).");
}

} // namespace kinstab::ui
