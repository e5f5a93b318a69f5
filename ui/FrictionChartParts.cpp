// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/FrictionChartParts.h"

#include "ui/NiceAxisTicks.h"

#include <QChart>
#include <QChartView>
#include <QLegendMarker>
#include <QValueAxis>

namespace kinstab::ui::friction {

ShownUnits shownUnits(UnitSystem s) {
    if (s == UnitSystem::US) return {1.0, 1.0, 1.0, 1.0, "kip", "psi", "in", "in²"};
    // 1 lbf = 4.4482216152605 N and 1 in = 25.4 mm exactly (NIST SP 811, appendix B).
    // psi = lbf/in²: 4.4482216152605e-3 kN over 0.0254² m² = 6.894757 kPa.
    const double kN = 4.4482216152605, kPa = kN * 1e-3 / (0.0254 * 0.0254);
    return {kN, kPa, 25.4, 6.4516, "kN", "kPa", "mm", "cm²"};
}

QColor cpColor(int i) {
    static const QColor colors[] = {QColor(0x1f77b4), QColor(0xd62728), QColor(0x2ca02c),
                                    QColor(0x9467bd), QColor(0xff7f0e), QColor(0x8c564b),
                                    QColor(0x17becf)};
    return colors[i % 7];
}

QValueAxis* axis(const QString& title, double lo, double hi) {
    auto* a = new QValueAxis;
    a->setTitleText(title);
    a->setRange(lo, hi);
    useNiceTicks(a);
    return a;
}

void resetChart(QChart* chart, const QList<QAbstractSeries*>& series, QValueAxis* x,
                QValueAxis* y) {
    chart->removeAllSeries();
    for (QAbstractAxis* a : chart->axes())
        chart->removeAxis(a), delete a;
    chart->addAxis(x, Qt::AlignBottom);
    chart->addAxis(y, Qt::AlignLeft);
    for (QAbstractSeries* s : series) {
        chart->addSeries(s);
        s->attachAxis(x);
        s->attachAxis(y);
        // Test points share their fit's colour; the legend lists the lines only.
        if (s->type() == QAbstractSeries::SeriesTypeScatter && s->property("hideInLegend").toBool())
            for (QLegendMarker* m : chart->legend()->markers(s))
                m->setVisible(false);
    }
}

QChartView* makeChartView(const QString& title) {
    auto* chart = new QChart;
    chart->setTitle(title);
    chart->setAnimationOptions(QChart::NoAnimation);
    chart->legend()->setAlignment(Qt::AlignRight);
    auto* view = new QChartView(chart);
    view->setRenderHint(QPainter::Antialiasing);
    // Two side by side fit the tab at 1280 × 800 (about 830 px): at 420 px each the tab
    // scrolled sideways and "Use this μ" was cut at the right.
    view->setMinimumSize(360, 340);
    return view;
}

} // namespace kinstab::ui::friction
