// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/CriticalChart.h"

#include "ui/DockedChart.h"
#include "ui/NiceAxisTicks.h"

#include <QLineSeries>
#include <QValueAxis>

#include <algorithm>

namespace kinstab::ui {

CriticalChart::CriticalChart(QWidget* parent)
    : QChartView(parent), m_curve(new QLineSeries), m_x(new QValueAxis), m_y(new QValueAxis) {
    auto* c = new QChart;
    c->setAnimationOptions(QChart::NoAnimation);
    c->setMargins(QMargins(4, 4, 4, 4));
    m_curve->setName(tr("A_crit(f)"));
    m_curve->setPen(QPen(QColor(30, 30, 30), 2.5));
    m_curve->setPointsVisible(true);
    c->addSeries(m_curve);
    m_x->setTitleText(tr("f (Hz)"));
    m_y->setTitleText(tr("A (g)"));
    c->addAxis(m_x, Qt::AlignBottom);
    c->addAxis(m_y, Qt::AlignLeft);
    m_curve->attachAxis(m_x);
    m_curve->attachAxis(m_y);
    QFont small = c->legend()->font();
    small.setPointSizeF(small.pointSizeF() * 0.85);
    c->legend()->setFont(small);
    useNiceTicks(c); // 1-2-5 ticks whatever range an update sets
    installDockedChart(this, c, tr("Critical amplitude A_crit(f) and the code ratios"));
}

void CriticalChart::setData(const SurfaceOverlays& o, double fMin, double fMax) {
    for (QLineSeries* s : m_lines) {
        chart()->removeSeries(s);
        delete s;
    }
    m_lines.clear();
    QList<QPointF> pts;
    double yMax = 0.0;
    for (const auto& [f, a] : o.aCrit) {
        pts.append({f, a});
        yMax = std::max(yMax, a);
    }
    m_curve->replace(pts);
    if (o.buildingFrequency) {
        fMin = std::min(fMin, *o.buildingFrequency);
        fMax = std::max(fMax, *o.buildingFrequency);
    }
    auto add = [&](const QString& name, const QColor& color, Qt::PenStyle style, QList<QPointF> p) {
        auto* s = new QLineSeries;
        s->setName(name);
        s->setPen(QPen(color, 2, style));
        s->replace(p);
        chart()->addSeries(s);
        s->attachAxis(m_x);
        s->attachAxis(m_y);
        m_lines.push_back(s);
    };
    for (const CodeRatio& c : o.codes) {
        add(tr("%1 %2").arg(c.name).arg(c.ratio, 0, 'f', 2), c.color, Qt::DashLine,
            {{fMin, c.ratio}, {fMax, c.ratio}});
        yMax = std::max(yMax, c.ratio);
    }
    if (yMax <= 0) yMax = 1;
    if (o.buildingFrequency)
        add(tr("1/T = %1 Hz").arg(*o.buildingFrequency, 0, 'f', 2), Qt::black, Qt::DotLine,
            {{*o.buildingFrequency, 0}, {*o.buildingFrequency, 1.1 * yMax}});
    m_x->setRange(fMin, fMax > fMin ? fMax : fMin + 1);
    m_y->setRange(0, 1.1 * yMax);
}

} // namespace kinstab::ui
