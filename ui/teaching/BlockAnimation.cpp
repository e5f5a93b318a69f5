// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/teaching/BlockAnimation.h"

#include "ui/NiceTicks.h"
#include "ui/teaching/BlockRun.h"
#include "ui/teaching/TextScale.h"

#include <QMouseEvent>
#include <QPainter>

#include <algorithm>
#include <cmath>

namespace kinstab::ui {

namespace {
constexpr double kLeft = 56, kRight = 10;
constexpr int kTracePoints = 600;

// One strip: a trace of f(t) over [0, end] with its zero line, ticks and title.
// guides: values drawn as dotted lines (theta = +-alpha: the block's corner above its pivot).
template <class F>
void paintStrip(QPainter& p, const QRectF& r, double end, const QString& title, const QColor& c,
                F f, std::initializer_list<double> guides = {}) {
    double lo = 0, hi = 0;
    std::vector<QPointF> pts;
    for (int k = 0; k <= kTracePoints; ++k) {
        const double t = end * k / kTracePoints, v = f(t);
        lo = std::min(lo, v);
        hi = std::max(hi, v);
        pts.emplace_back(t, v);
    }
    if (hi - lo < 1e-9) hi = lo + 1;
    const int ticks = r.height() < 90 ? 2 : 4; // a short strip: fewer labels, none overlapping
    const NiceAxis ax = niceAxis(lo, hi, ticks);
    auto X = [&](double t) { return r.left() + t / end * r.width(); };
    auto Y = [&](double v) { return r.bottom() - (v - ax.min) / (ax.max - ax.min) * r.height(); };
    p.setPen(QPen(QColor(0xcc, 0xcc, 0xcc), 1.0));
    p.drawRect(r);
    p.setPen(QColor(0x55, 0x55, 0x55));
    for (double v = ax.min; v <= ax.max + ax.step / 2; v += ax.step) {
        p.drawLine(QPointF(r.left() - 4, Y(v)), QPointF(r.left(), Y(v)));
        const QString s = QString::number(v, 'f', ax.decimals());
        p.drawText(QRectF(r.left() - kLeft, Y(v) - 8, kLeft - 6, 16),
                   Qt::AlignRight | Qt::AlignVCenter, s);
    }
    p.setPen(QPen(QColor(0x99, 0x99, 0x99), 1.0, Qt::DotLine));
    p.drawLine(QPointF(r.left(), Y(0)), QPointF(r.right(), Y(0)));
    p.setPen(QPen(QColor(0xc0, 0x39, 0x2b), 1.0, Qt::DotLine));
    for (double g : guides)
        if (g > ax.min && g < ax.max) p.drawLine(QPointF(r.left(), Y(g)), QPointF(r.right(), Y(g)));
    QPolygonF line;
    for (const QPointF& q : pts)
        line << QPointF(X(q.x()), Y(q.y()));
    p.setPen(QPen(c, 1.6));
    p.drawPolyline(line);
    p.setPen(c.darker(130));
    p.drawText(QPointF(r.left() + 6, r.top() + 14), title);
}
} // namespace

BlockAnimation::BlockAnimation(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("blockAnimation"));
}

void BlockAnimation::setScene(const BlockScene& scene) {
    scene_ = scene;
    update();
}

void BlockAnimation::paintEvent(QPaintEvent*) {
    QPainter p(this);
    paintBlockScene(p, rect(), scene_);
}

BlockTraces::BlockTraces(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("blockTraces"));
}

void BlockTraces::setRun(const BlockRun* run) {
    run_ = run;
    update();
}

void BlockTraces::setCursor(double t) {
    cursor_ = t;
    update();
}

double BlockTraces::timeAt(double x) const {
    if (!run_) return 0;
    const double w = std::max(1.0, width() - kLeft - kRight);
    return std::clamp((x - kLeft) / w, 0.0, 1.0) * run_->end();
}

void BlockTraces::paintEvent(QPaintEvent*) {
    QPainter p(this);
    p.fillRect(rect(), Qt::white);
    if (!run_) return;
    p.setRenderHint(QPainter::Antialiasing);
    QFont f = p.font();
    f.setPixelSize(scaledPixels(p, 12, kLabelMaxScale));
    p.setFont(f);
    const double end = run_->end(), alpha = run_->alpha();
    const double bottomPad = 22, gap = 8;
    const double h = (height() - bottomPad - gap - 4) / 2;
    const QRectF top(kLeft, 4, width() - kLeft - kRight, h);
    const QRectF low(kLeft, top.bottom() + gap, top.width(), h);
    paintStrip(p, top, end, tr("θ/α (> 0: on the right corner; ±1: centre above the corner)"),
               QColor(0x2e, 0x8b, 0x57), [&](double t) { return run_->at(t).theta / alpha; },
               {-1.0, 1.0});
    paintStrip(p, low, end, tr("base acceleration a/g"), QColor(0x20, 0x40, 0x90),
               [&](double t) { return run_->baseAcceleration(t); });
    // The impacts as ticks on the top strip, the overturning as a red line.
    p.setPen(QPen(QColor(0xe6, 0x7e, 0x22), 1.5));
    for (double ti : run_->result().impactTimes) {
        const double x = top.left() + ti / end * top.width();
        p.drawLine(QPointF(x, top.bottom() - 8), QPointF(x, top.bottom()));
    }
    if (run_->result().overturnTime) {
        const double x = top.left() + *run_->result().overturnTime / end * top.width();
        p.setPen(QPen(QColor(0xc0, 0x39, 0x2b), 1.5, Qt::DashLine));
        p.drawLine(QPointF(x, top.top()), QPointF(x, low.bottom()));
    }
    const double xc = top.left() + std::clamp(cursor_ / end, 0.0, 1.0) * top.width();
    p.setPen(QPen(QColor(0x20, 0x20, 0x20), 1.2));
    p.drawLine(QPointF(xc, top.top()), QPointF(xc, low.bottom()));
    p.setPen(QColor(0x55, 0x55, 0x55));
    for (double t : niceTicks(0, end, 8))
        p.drawText(QRectF(low.left() + t / end * low.width() - 30, low.bottom() + 2, 60, 16),
                   Qt::AlignCenter, QString::number(t, 'g', 4));
    p.drawText(QRectF(low.right() - 60, low.bottom() + 2, 60, 16), Qt::AlignRight, tr("t, s"));
}

void BlockTraces::mousePressEvent(QMouseEvent* e) {
    emit seekRequested(timeAt(e->position().x()));
}

void BlockTraces::mouseMoveEvent(QMouseEvent* e) {
    if (e->buttons() & Qt::LeftButton) emit seekRequested(timeAt(e->position().x()));
}

} // namespace kinstab::ui
