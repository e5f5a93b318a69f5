// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/DockedChart.h"

#include "ui/LegendEntry.h"

#include <QChart>
#include <QEvent>
#include <QLabel>
#include <QLegend>
#include <QLegendMarker>

namespace kinstab::ui {

namespace {

const char* const kNoLegend = "kinstabNoLegend"; // set on a series hideFromLegend() keeps out

// The chart's title and legend as labels that wrap onto more lines: QChart puts each on one line
// and elides it ("γc and τc against A at f = 1.125 Hz (cf…", "sli…", "A…") when it does not fit,
// and three docks along a 1280 px window are about 270 px wide. The title label sits at the top
// of the view and the legend label along the bottom (render() and grab() include both); the
// chart's own title is kept, for the SVG export, but drawn transparent in a 1 px font, and the
// chart's margins make room for the labels. The labels follow the title and the legend as they
// are whenever the chart paints: the charts retitle, rename, hide and add series in many places.
class WrappingTexts : public QObject {
public:
    explicit WrappingTexts(QChartView* view)
        : QObject(view), m_view(view),
          m_title(label(view, "chartTitle", view->chart()->titleFont())),
          m_legend(label(view, "chartLegend", view->chart()->legend()->font())),
          m_margins(view->chart()->margins()) {
        QChart* chart = view->chart();
        QPalette palette = m_title->palette();
        palette.setBrush(QPalette::WindowText, chart->titleBrush());
        m_title->setPalette(palette);
        QFont hidden = chart->titleFont();
        hidden.setPixelSize(1);
        chart->setTitleFont(hidden);
        chart->setTitleBrush(Qt::transparent);
        chart->legend()->setVisible(false);
        // The chart's card would stop short of the labels: the view is the card instead.
        view->setBackgroundBrush(chart->backgroundBrush());
        chart->setBackgroundVisible(false);
        view->installEventFilter(this);
        view->viewport()->installEventFilter(this);
    }

    bool eventFilter(QObject*, QEvent* e) override {
        if (e->type() == QEvent::Paint || e->type() == QEvent::Resize) update();
        return false;
    }

private:
    static QLabel* label(QWidget* parent, const char* name, const QFont& font) {
        auto* l = new QLabel(parent);
        l->setObjectName(QString::fromLatin1(name)); // tests find them by name
        l->setTextFormat(Qt::RichText);
        l->setWordWrap(true);
        l->setAlignment(Qt::AlignHCenter);
        l->setFont(font);
        l->setAttribute(Qt::WA_TransparentForMouseEvents);
        return l;
    }

    // One entry per named series not kept out of the legend; a line breaks only between
    // entries. (A marker of a hidden legend reports itself invisible: the series carries the mark.)
    QString legendHtml() const {
        QStringList entries;
        for (QLegendMarker* m : m_view->chart()->legend()->markers()) {
            if (m->label().isEmpty() || !m->series()->isVisible() ||
                m->series()->property(kNoLegend).toBool())
                continue;
            const QColor c =
                m->brush().style() != Qt::NoBrush ? m->brush().color() : m->pen().color();
            entries << legendEntryHtml(c, m->label().toHtmlEscaped());
        }
        return entries.join(QStringLiteral("&nbsp;&nbsp; "));
    }

    // Sets the label's text and returns its height at `width` (0: empty, hidden).
    static int fill(QLabel* l, const QString& text, int width) {
        l->setText(text);
        const int h = text.isEmpty() ? 0 : l->heightForWidth(width);
        l->setVisible(h > 0);
        return h;
    }

    void update() {
        const QString title = m_view->chart()->title(), legend = legendHtml();
        const int width = m_view->width() - 8, height = m_view->height();
        if (title == m_titleText && legend == m_legendText && width == m_width &&
            height == m_height)
            return;
        m_titleText = title;
        m_legendText = legend;
        m_width = width;
        m_height = height;
        const int top = fill(m_title, title, width);
        const int bottom = fill(m_legend, legend, width);
        m_title->setGeometry(4, m_margins.top(), width, top);
        m_legend->setGeometry(4, height - bottom - 2, width, bottom);
        QMargins margins = m_margins;
        margins.setTop(m_margins.top() + top);
        margins.setBottom(m_margins.bottom() + bottom + 2);
        m_view->chart()->setMargins(margins);
    }

    QChartView* m_view;
    QLabel* m_title;
    QLabel* m_legend;
    QMargins m_margins; // the chart's own, before the labels' room
    QString m_titleText, m_legendText;
    int m_width = -1, m_height = -1;
};

} // namespace

void installDockedChart(QChartView* view, QChart* chart, const QString& title) {
    chart->setTitle(title);
    view->setChart(chart);
    view->setRenderHint(QPainter::Antialiasing);
    view->setMinimumSize(240, 160);
    new WrappingTexts(view);
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
