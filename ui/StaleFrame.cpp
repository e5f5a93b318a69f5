// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/StaleFrame.h"

#include <QGridLayout>
#include <QLabel>
#include <QPainter>

namespace kinstab::ui {

namespace {
// Lays white at 60 % over whatever lies under it: the result stays readable but cannot pass
// for a current one. (An opacity effect on a chart view renders it dark and elides its labels.)
class Veil : public QWidget {
public:
    explicit Veil(QWidget* parent) : QWidget(parent) {
        setAttribute(Qt::WA_TransparentForMouseEvents);
    }

protected:
    void paintEvent(QPaintEvent*) override {
        QPainter(this).fillRect(rect(), QColor(255, 255, 255, 155));
    }
};
} // namespace

QString StaleFrame::staleText() {
    return tr("inputs changed — Run to update");
}

QString StaleFrame::staleStyle() {
    return QStringLiteral("background: #fde2c8; color: #7a3300; font-weight: bold;");
}

StaleFrame::StaleFrame(QWidget* view, QWidget* parent)
    : QWidget(parent), m_view(view), m_line(new QLabel(staleText(), this)), m_veil(new Veil(this)) {
    auto* layout = new QGridLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(0);
    m_line->setContentsMargins(8, 3, 8, 3);
    m_line->setStyleSheet(staleStyle());
    m_line->setToolTip(tr("This result was computed with other inputs than the panels now show."));
    m_line->hide();
    // One cell: the view, the veil over it, the line over the view's top edge, so marking a
    // result stale does not shrink its chart (whose axis labels would then be elided).
    layout->addWidget(view, 0, 0);
    layout->addWidget(m_veil, 0, 0);
    layout->addWidget(m_line, 0, 0, Qt::AlignTop);
    m_veil->hide();
}

void StaleFrame::setStale(bool stale) {
    m_stale = stale;
    m_line->setVisible(stale);
    m_veil->setVisible(stale);
    if (stale) {
        m_veil->raise();
        m_line->raise();
    }
}

} // namespace kinstab::ui
