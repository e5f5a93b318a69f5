// SPDX-License-Identifier: GPL-3.0-or-later
#include "report/WrappedText.h"

#include <QFontMetricsF>
#include <QTextLayout>

#include <cmath>

namespace kinstab::report {

namespace {

QTextOption wrapOption(Qt::Alignment align) {
    QTextOption o(align);
    o.setWrapMode(QTextOption::WrapAtWordBoundaryOrAnywhere);
    return o;
}

// QTextLayout breaks lines at U+2028, not at "\n", as QPainter::drawText does when it lays out.
QString withLineSeparators(QString text) {
    return text.replace(QLatin1Char('\n'), QChar::LineSeparator);
}

// Lays the text out in lines of `width`, spaced as QPainter::drawText spaces them (the font's
// leading between lines, each line on a whole device unit). Returns the height.
double layOut(QTextLayout& layout, double width, QPaintDevice* device) {
    const double leading = QFontMetricsF(layout.font(), device).leading();
    double height = -leading;
    layout.beginLayout();
    for (QTextLine line = layout.createLine(); line.isValid(); line = layout.createLine()) {
        line.setLineWidth(width);
        height = std::ceil(height + leading);
        line.setPosition(QPointF(0, height));
        height += line.height();
    }
    layout.endLayout();
    return std::max(0.0, height);
}

} // namespace

double wrappedHeight(const QString& text, const QFont& font, double width, QPaintDevice* device) {
    if (text.isEmpty()) return 0;
    QTextLayout layout(withLineSeparators(text), font, device);
    layout.setTextOption(wrapOption(Qt::AlignLeft));
    return layOut(layout, width, device);
}

void paintWrapped(QPainter& p, const QRectF& r, const QString& text, Qt::Alignment align) {
    if (text.isEmpty()) return;
    QTextLayout layout(withLineSeparators(text), p.font(), p.device());
    layout.setTextOption(wrapOption(align));
    layOut(layout, r.width(), p.device());
    layout.draw(&p, r.topLeft());
}

QString elidedToLines(const QString& text, const QFont& font, double width, int lines,
                      QPaintDevice* device) {
    const QString t = withLineSeparators(text);
    QTextLayout layout(t, font, device);
    layout.setTextOption(wrapOption(Qt::AlignLeft));
    layOut(layout, width, device);
    if (layout.lineCount() <= lines || lines < 1) return text;
    const QTextLine last = layout.lineAt(lines - 1);
    QString kept = t.left(last.textStart());
    QString rest = t.mid(last.textStart()).replace(QChar::LineSeparator, QLatin1Char(' '));
    kept.replace(QChar::LineSeparator, QLatin1Char('\n'));
    return kept + QFontMetricsF(font, device).elidedText(rest, Qt::ElideRight, width);
}

} // namespace kinstab::report
