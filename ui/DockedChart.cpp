// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/DockedChart.h"

#include <QEvent>
#include <QLabel>
#include <QLegend>
#include <QLegendMarker>

namespace kinstab::ui {

namespace {

const char* const kNoLegend = "kinstabNoLegend"; // set on a series hideFromLegend() keeps out

// The chart's legend as a label that wraps its entries onto more lines: QLegend puts them on one
// line and elides every label when they do not fit, and three docks along a 1280 px window are
// too narrow for five entries. The label sits along the bottom of the view (render() and grab()
// include it; the chart lays its title out at the top margin, so the legend cannot go above
// it), and the chart's bottom margin makes room. It follows the legend as
// it is whenever the chart paints: the charts rename, hide and add series in many places.
class WrappingLegend : public QObject {
public:
    explicit WrappingLegend(QChartView* view)
        : QObject(view), m_view(view), m_label(new QLabel(view)),
          m_margins(view->chart()->margins()) {
        QLegend* legend = view->chart()->legend();
        legend->setVisible(false);
        m_label->setObjectName(QStringLiteral("chartLegend")); // tests find it by name
        m_label->setTextFormat(Qt::RichText);
        m_label->setWordWrap(true);
        m_label->setAlignment(Qt::AlignHCenter);
        m_label->setFont(legend->font());
        m_label->setAttribute(Qt::WA_TransparentForMouseEvents);
        view->installEventFilter(this);
        view->viewport()->installEventFilter(this);
    }

    bool eventFilter(QObject*, QEvent* e) override {
        if (e->type() == QEvent::Paint || e->type() == QEvent::Resize) update();
        return false;
    }

private:
    // One entry per named series not kept out of the legend; a line breaks only between
    // entries. (A marker of a hidden legend reports itself invisible: the series carries the mark.)
    QString html() const {
        QStringList entries;
        for (QLegendMarker* m : m_view->chart()->legend()->markers()) {
            if (m->label().isEmpty() || !m->series()->isVisible() ||
                m->series()->property(kNoLegend).toBool())
                continue;
            const QColor c =
                m->brush().style() != Qt::NoBrush ? m->brush().color() : m->pen().color();
            entries << QStringLiteral("<span style='white-space:nowrap'><span "
                                      "style='color:%1'>&#9632;</span> %2</span>")
                           .arg(c.name(), m->label().toHtmlEscaped());
        }
        return entries.join(QStringLiteral("&nbsp;&nbsp; "));
    }

    void update() {
        const QString text = html();
        const int width = m_view->width() - 8;
        const int height = m_view->height();
        if (text == m_text && width == m_width && height == m_height) return;
        m_text = text;
        m_width = width;
        m_height = height;
        m_label->setText(text);
        const int h = text.isEmpty() ? 0 : m_label->heightForWidth(width);
        QMargins margins = m_margins;
        m_label->setGeometry(4, height - h - 2, width, h);
        margins.setBottom(m_margins.bottom() + h + 2);
        m_label->setVisible(h > 0);
        m_view->chart()->setMargins(margins);
    }

    QChartView* m_view;
    QLabel* m_label;
    QMargins m_margins; // the chart's own, before the legend's room
    QString m_text;
    int m_width = -1, m_height = -1;
};

} // namespace

void installDockedChart(QChartView* view, QChart* chart, const QString& title) {
    chart->setTitle(title);
    view->setChart(chart);
    view->setRenderHint(QPainter::Antialiasing);
    view->setMinimumSize(240, 160);
    new WrappingLegend(view);
}

QLineSeries* chartLine(const QString& name, const QColor& color, qreal width, Qt::PenStyle style) {
    auto* s = new QLineSeries;
    s->setName(name);
    s->setPen(QPen(color, width, style));
    return s;
}

void hideFromLegend(QChart* chart, std::initializer_list<QAbstractSeries*> series) {
    for (QAbstractSeries* s : series) {
        s->setProperty(kNoLegend, true);
        for (QLegendMarker* marker : chart->legend()->markers(s))
            marker->setVisible(false);
    }
}

} // namespace kinstab::ui
