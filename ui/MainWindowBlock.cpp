// SPDX-License-Identifier: GPL-3.0-or-later
// MainWindow, continued: the free-standing block model (ModelPanel's third choice). The centre's
// first tab shows its overturning map (ui/BlockMapView.h) instead of the γc surface; Run and
// Cancel drive the map's job, with the status bar's progress; the map dims when the block's
// inputs change.

#include "ui/BlockMapView.h"
#include "ui/MainWindow.h"
#include "ui/ModelPanel.h"
#include "ui/RunProgress.h"
#include "ui/SurfaceView.h"
#include "ui/teaching/BlockTeachingView.h"
#include "ui/teaching/TeachingView.h"

#include <QComboBox>

#include <QLabel>
#include <QStackedWidget>
#include <QStatusBar>
#include <QTabWidget>

namespace kinstab::ui {

QWidget* MainWindow::buildBlockMap() {
    m_resultStack = new QStackedWidget;
    m_resultStack->addWidget(m_surface);
    m_blockMap = new BlockMapView;
    m_resultStack->addWidget(m_blockMap);
    connect(m_blockMap, &BlockMapView::progress, this, &MainWindow::showProgress);
    connect(m_blockMap, &BlockMapView::finished, this, [this](bool, const QString& message) {
        m_progress->finish();
        m_status->setText(message);
        updateRunState();
        emit blockMapFinished();
    });
    return m_resultStack;
}

// The model chosen decides what the first tab shows and what Run computes.
void MainWindow::showModelView() {
    const bool block = m_modelPanel->isBlock();
    m_resultStack->setCurrentWidget(block ? static_cast<QWidget*>(m_blockMap) : m_surface);
    const bool planarSurface = m_results.surface() && m_results.surface()->planar;
    m_centre->setTabText(0, block           ? tr("Overturning map")
                            : planarSurface ? tr("γc surface — planar")
                                            : tr("γc surface"));
    m_blockMap->setInputs(m_modelPanel->blockSettings());
}

void MainWindow::runBlockMap() {
    if (!m_modelPanel->isValid() || m_blockMap->isRunning()) return;
    const BlockMapSettings s = m_modelPanel->blockSettings();
    statusBar()->clearMessage();
    m_progress->start(2LL * s.points * s.points, tr("points"));
    m_status->setText(tr("Computing the overturning map: %1, 2 × %2 × %2 points…")
                          .arg(blockMapTitle(s))
                          .arg(s.points));
    m_blockMap->run(s);
    updateRunState();
}

// The Teaching tab animates the slab on its walls or a free-standing block; the choice sits in
// the tab bar's corner (no row of its own: the tab must fit 1280 × 800) and shows only there.
QWidget* MainWindow::buildTeachingStack() {
    auto* stack = new QStackedWidget;
    stack->addWidget(m_teaching);
    m_blockTeaching = new BlockTeachingView;
    stack->addWidget(m_blockTeaching);
    m_teachingSubject = new QComboBox;
    m_teachingSubject->setObjectName(QStringLiteral("teachingSubject"));
    m_teachingSubject->addItem(tr("Slab on its walls"));
    m_teachingSubject->addItem(tr("Free-standing block"));
    m_teachingSubject->setToolTip(tr("What the Teaching tab animates"));
    connect(m_teachingSubject, &QComboBox::currentIndexChanged, stack,
            &QStackedWidget::setCurrentIndex);
    m_centre->setCornerWidget(m_teachingSubject, Qt::TopRightCorner);
    m_teachingSubject->hide();
    connect(m_centre, &QTabWidget::currentChanged, this, [this, stack](int) {
        const QWidget* w = m_centre->currentWidget();
        m_teachingSubject->setVisible(w && w->isAncestorOf(stack));
    });
    return stack;
}

} // namespace kinstab::ui
