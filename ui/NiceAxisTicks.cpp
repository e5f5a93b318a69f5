// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/NiceAxisTicks.h"

#include "ui/NiceTicks.h"

#include <QChart>
#include <QValueAxis>

#include <cmath>

namespace kinstab::ui {

namespace {
const char* const kNice = "kinstabNiceTicks"; // set once: one connection per axis

void retick(QValueAxis* a, int maxTicks) {
    const double lo = a->min(), hi = a->max();
    if (!(hi > lo) || !std::isfinite(hi - lo)) return;
    NiceAxis n;
    n.step = niceStep(lo, hi, maxTicks);
    a->setTickType(QValueAxis::TicksDynamic);
    a->setTickAnchor(0.0);
    a->setTickInterval(n.step);
    a->setLabelFormat(QStringLiteral("%.%1f").arg(n.decimals()));
    // A second y axis on the right ticks on its own steps: its grid lines would cross the left
    // axis's, a second grid. Its labels are enough.
    if (a->alignment() == Qt::AlignRight) a->setGridLineVisible(false);
}
} // namespace

void useNiceTicks(QValueAxis* axis, int maxTicks) {
    if (!axis || axis->property(kNice).toBool()) return;
    axis->setProperty(kNice, true);
    QObject::connect(axis, &QValueAxis::rangeChanged, axis,
                     [axis, maxTicks] { retick(axis, maxTicks); });
    retick(axis, maxTicks);
}

void useNiceTicks(QChart* chart, int maxTicks) {
    for (QAbstractAxis* a : chart->axes())
        if (auto* v = qobject_cast<QValueAxis*>(a)) useNiceTicks(v, maxTicks);
}

} // namespace kinstab::ui
