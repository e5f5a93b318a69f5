// SPDX-License-Identifier: GPL-3.0-or-later
// MainWindow, continued: the docks (the input panels and the verdict on the left, the result
// charts along the bottom), their first-start layout and View → Reset layout.

#include "ui/BuildingPanel.h"
#include "ui/CodesPanel.h"
#include "ui/CriticalChart.h"
#include "ui/ExcitationPanel.h"
#include "ui/GridPanel.h"
#include "ui/HistoryChart.h"
#include "ui/MainWindow.h"
#include "ui/ModelPanel.h"
#include "ui/PlanarHistoryChart.h"
#include "ui/RecordsTab.h"
#include "ui/Scrollable.h"
#include "ui/SlabPanel.h"
#include "ui/SliceChart.h"
#include "ui/StaleFrame.h"
#include "ui/SurfaceView.h"
#include "ui/TabDocks.h"
#include "ui/VerdictPanel.h"

#include <QDockWidget>
#include <QMenu>
#include <QStackedWidget>
#include <QTabWidget>

#include <algorithm>

namespace kinstab::ui {

// The result chart docks give their room to the tabs that do not show them.
void MainWindow::buildTabDocks() {
    m_tabDocks = new TabDocks(
        m_centre, m_chartDocks,
        [this](int i) {
            // The first tab holds the surface (or the block's map) in a stack.
            return m_centre->widget(i)->isAncestorOf(m_surface) ||
                   m_centre->widget(i)->isAncestorOf(m_records);
        },
        this);
}

QDockWidget* MainWindow::addPanelDock(const QString& title, QWidget* w, Qt::DockWidgetArea area) {
    auto* dock = new QDockWidget(title, this);
    dock->setObjectName(
        title.simplified().remove(QLatin1Char('&')).replace(QLatin1Char(' '), QLatin1Char('_')) +
        "Dock");
    dock->setWidget(w);
    addDockWidget(area, dock);
    m_viewMenu->addAction(dock->toggleViewAction());
    return dock;
}

void MainWindow::buildDocks() {
    // Short titles: six tabs share the inputs' dock and must not be cut at 1280 px.
    const std::pair<QString, QWidget*> inputs[] = {
        {tr("Building"), m_building}, {tr("Codes"), m_codesPanel},  {tr("Slab"), m_slabPanel},
        {tr("Model"), m_modelPanel},  {tr("Motion"), m_excitation}, {tr("Grid"), m_gridPanel}};
    for (const auto& [title, w] : inputs)
        m_inputDocks.push_back(addPanelDock(title, scrollable(w), Qt::LeftDockWidgetArea));
    m_verdictFrame = new StaleFrame(m_verdict);
    m_verdictDock = addPanelDock(tr("Verdict"), m_verdictFrame, Qt::LeftDockWidgetArea);
    m_sliceFrame = new StaleFrame(m_slice);
    m_historyStack = new QStackedWidget;
    m_historyStack->addWidget(m_history);
    m_historyStack->addWidget(m_planarHistory);
    m_historyFrame = new StaleFrame(m_historyStack);
    m_criticalFrame = new StaleFrame(m_critical);
    m_chartDocks = {addPanelDock(tr("γc, τc against A"), m_sliceFrame, Qt::BottomDockWidgetArea),
                    addPanelDock(tr("History"), m_historyFrame, Qt::BottomDockWidgetArea),
                    addPanelDock(tr("A_crit(f)"), m_criticalFrame, Qt::BottomDockWidgetArea)};
    m_viewMenu->addSeparator();
    m_viewMenu->addAction(tr("Reset &layout"), this, &MainWindow::resetLayout);
}

// The inputs tabbed on the left above the verdict; the three charts side by side along the
// bottom, below the surface only (the left column runs the full height), with a third of it.
void MainWindow::arrangeDocks() {
    setCorner(Qt::BottomLeftCorner, Qt::LeftDockWidgetArea);
    for (QDockWidget* d : m_inputDocks)
        addDockWidget(Qt::LeftDockWidgetArea, d);
    addDockWidget(Qt::LeftDockWidgetArea, m_verdictDock);
    splitDockWidget(m_inputDocks.front(), m_verdictDock, Qt::Vertical);
    for (std::size_t i = 1; i < m_inputDocks.size(); ++i)
        tabifyDockWidget(m_inputDocks.front(), m_inputDocks[i]);
    for (QDockWidget* d : m_chartDocks)
        addDockWidget(Qt::BottomDockWidgetArea, d);
    splitDockWidget(m_chartDocks[0], m_chartDocks[1], Qt::Horizontal);
    splitDockWidget(m_chartDocks[1], m_chartDocks[2], Qt::Horizontal);
    std::vector<QDockWidget*> all = m_inputDocks;
    all.push_back(m_verdictDock);
    all.insert(all.end(), m_chartDocks.begin(), m_chartDocks.end());
    for (QDockWidget* d : all) {
        d->setFloating(false);
        d->show();
    }
    m_inputDocks.front()->raise();
    const int h = height();
    resizeDocks({m_inputDocks.front(), m_verdictDock}, {h * 55 / 100, h * 45 / 100}, Qt::Vertical);
    resizeDocks({m_inputDocks.front()}, {std::max(430, width() * 30 / 100)}, Qt::Horizontal);
    resizeDocks({m_chartDocks.front()}, {std::max(240, h * 34 / 100)}, Qt::Vertical);
    const int w = std::max(300, (width() - 430) / 3);
    resizeDocks({m_chartDocks[0], m_chartDocks[1], m_chartDocks[2]}, {w, w, w}, Qt::Horizontal);
}

void MainWindow::resetLayout() {
    arrangeDocks();
}

} // namespace kinstab::ui
