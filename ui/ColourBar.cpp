// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/ColourBar.h"

#include "ui/NiceTicks.h"

#include <QPainter>

#include <algorithm>
#include <cmath>

namespace kinstab::ui {

namespace {
constexpr int kBarWidth = 16;
constexpr int kMaxTicks = 6;

QString tickText(double v, int decimals) {
    return QString::number(v, 'f', decimals); // 'f' is locale-independent
}
} // namespace

QColor gammaColor(double t) {
    // Stable (0) dark blue, then through teal and yellow to red at the largest γc.
    static const QColor stops[] = {QColor(40, 60, 140), QColor(30, 150, 160), QColor(240, 220, 60),
                                   QColor(215, 50, 40)};
    t = std::clamp(t, 0.0, 1.0) * 3.0;
    const int i = std::min(static_cast<int>(t), 2);
    const double u = t - i;
    auto mix = [&](int a, int b) { return static_cast<int>(a + (b - a) * u); };
    return QColor(mix(stops[i].red(), stops[i + 1].red()),
                  mix(stops[i].green(), stops[i + 1].green()),
                  mix(stops[i].blue(), stops[i + 1].blue()));
}

QColor notComputedColor() {
    return QColor(205, 205, 205);
}

double colourScaleMaximum(const GammaGrid& g) {
    double gMax = 0;
    for (double v : g.gamma)
        if (std::isfinite(v)) gMax = std::max(gMax, v);
    return gMax > 0 ? niceAxis(0, gMax, 6).max : 1.0;
}

int colourBarWidth(const QFontMetrics& fm, double gMax) {
    const NiceAxis axis = niceAxis(0, gMax, kMaxTicks);
    int w = 0;
    for (double t : niceTicks(0, gMax, kMaxTicks))
        w = std::max(w, fm.horizontalAdvance(tickText(t, axis.decimals())));
    return kBarWidth + 6 + w;
}

void paintColourBar(QPainter& p, const QRectF& bar, double gMax, const QString& title, bool faded) {
    if (!(gMax > 0)) gMax = 1;
    const QRectF r(bar.left(), bar.top(), kBarWidth, bar.height());
    QLinearGradient g(r.bottomLeft(), r.topLeft());
    for (double t : {0.0, 1.0 / 3, 2.0 / 3, 1.0}) // the stops of gammaColor()
        g.setColorAt(t, gammaColor(t));
    p.save();
    p.fillRect(r, g);
    if (faded) p.fillRect(r, QColor(255, 255, 255, 165));
    p.setPen(p.pen().color());
    p.setBrush(Qt::NoBrush);
    p.drawRect(r);
    const QFontMetricsF fm(p.font());
    const int decimals = niceAxis(0, gMax, kMaxTicks).decimals();
    for (double t : niceTicks(0, gMax, kMaxTicks)) {
        const double y = r.bottom() - t / gMax * r.height();
        p.drawLine(QPointF(r.right(), y), QPointF(r.right() + 4, y));
        p.drawText(QPointF(r.right() + 6, y + fm.ascent() / 2 - 1), tickText(t, decimals));
    }
    p.drawText(QPointF(r.left(), r.top() - fm.descent() - 3), title);
    p.restore();
}

ColourBar::ColourBar(QWidget* parent) : QWidget(parent) {
    setSizePolicy(QSizePolicy::Fixed, QSizePolicy::Expanding);
    setToolTip(tr("Colour scale of γc: dark blue is stable (γc = 0), red the fastest collapse "
                  "on this grid."));
}

void ColourBar::setRange(double gMax, const QString& title) {
    m_gMax = gMax > 0 ? gMax : 1;
    m_title = title;
    updateGeometry();
    update();
}

void ColourBar::setFaded(bool faded) {
    m_faded = faded;
    update();
}

QSize ColourBar::sizeHint() const {
    const QFontMetrics fm(font());
    return {std::max(colourBarWidth(fm, m_gMax), fm.horizontalAdvance(m_title)) + 14, 300};
}

QSize ColourBar::minimumSizeHint() const {
    return {sizeHint().width(), 120};
}

void ColourBar::paintEvent(QPaintEvent*) {
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    p.setPen(palette().text().color());
    const QFontMetrics fm(font());
    const int top = fm.height() + 10;
    paintColourBar(p, QRectF(6, top, 16, height() - top - fm.height()), m_gMax, m_title, m_faded);
}

} // namespace kinstab::ui
