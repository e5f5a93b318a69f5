// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/teaching/TracePlot.h"

#include "ui/teaching/TracePainter.h"

#include <QMouseEvent>
#include <QPainter>

namespace kinstab::ui {

TracePlot::TracePlot(QWidget* parent) : QWidget(parent) {
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
    setAttribute(Qt::WA_OpaquePaintEvent);
    setToolTip(tr("Click or drag to move through the run"));
}

void TracePlot::setRun(const TeachingRun* run) {
    run_ = run;
    update();
}

void TracePlot::setCursor(double tau) {
    cursor_ = tau;
    update();
}

void TracePlot::paintEvent(QPaintEvent*) {
    QPainter p(this);
    if (run_)
        paintTraces(p, rect(), *run_, cursor_);
    else
        p.fillRect(rect(), Qt::white);
}

void TracePlot::mousePressEvent(QMouseEvent* e) {
    if (run_ && e->button() == Qt::LeftButton)
        emit seekRequested(
            traceLayout(rect(), *run_, traceLabelPixels(font())).tauAt(e->position().x()));
}

void TracePlot::mouseMoveEvent(QMouseEvent* e) {
    if (run_ && (e->buttons() & Qt::LeftButton))
        emit seekRequested(
            traceLayout(rect(), *run_, traceLabelPixels(font())).tauAt(e->position().x()));
}

} // namespace kinstab::ui
