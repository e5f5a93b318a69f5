#include "ui/StaleFrame.h"

#include <QGraphicsOpacityEffect>
#include <QLabel>
#include <QVBoxLayout>

namespace kinstab::ui {

QString StaleFrame::staleText() {
    return tr("inputs changed — Run to update");
}

QString StaleFrame::staleStyle() {
    return QStringLiteral("background: #fde2c8; color: #7a3300; font-weight: bold;");
}

StaleFrame::StaleFrame(QWidget* view, QWidget* parent)
    : QWidget(parent), m_view(view), m_line(new QLabel(staleText(), this)),
      m_dim(new QGraphicsOpacityEffect(this)) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(0);
    m_line->setContentsMargins(8, 3, 8, 3);
    m_line->setStyleSheet(staleStyle());
    m_line->setToolTip(tr("This result was computed with other inputs than the panels now show."));
    m_line->hide();
    layout->addWidget(m_line);
    layout->addWidget(view, 1);
    m_dim->setOpacity(0.35);
    m_dim->setEnabled(false);
    view->setGraphicsEffect(m_dim);
}

void StaleFrame::setStale(bool stale) {
    m_stale = stale;
    m_line->setVisible(stale);
    m_dim->setEnabled(stale);
}

} // namespace kinstab::ui
