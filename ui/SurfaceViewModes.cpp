// SPDX-License-Identifier: GPL-3.0-or-later
// SurfaceView, continued: its three views (3D, from straight above, the 2D map), the tool bar
// that chooses one, and the page the stack shows for it.

#include "ui/ColourBar.h"
#include "ui/HeatMapView.h"
#include "ui/SurfaceGraph3D.h"
#include "ui/SurfaceView.h"

#include <QButtonGroup>
#include <QHBoxLayout>
#include <QLabel>
#include <QStackedWidget>
#include <QToolButton>

namespace kinstab::ui {

QWidget* SurfaceView::buildToolBar() {
    auto* bar = new QWidget(this);
    auto* h = new QHBoxLayout(bar);
    h->setContentsMargins(4, 2, 4, 2);
    auto* group = new QButtonGroup(bar);
    const struct {
        SurfaceMode mode;
        const char* name;
        QString text, tip;
    } modes[] = {
        {SurfaceMode::Surface3D, "view3D", tr("3D"), tr("The γc surface in 3D (drag to rotate)")},
        {SurfaceMode::Top, "viewTop", tr("Top view"),
         tr("The 3D surface seen from straight above")},
        {SurfaceMode::Map, "viewMap", tr("2D map"), tr("γc as a flat colour map with its axes")},
    };
    for (const auto& m : modes) {
        auto* b = new QToolButton(bar);
        b->setObjectName(QLatin1String(m.name));
        b->setText(m.text);
        b->setToolTip(m.tip);
        b->setCheckable(true);
        b->setEnabled(m_3d || m.mode == SurfaceMode::Map);
        group->addButton(b);
        connect(b, &QToolButton::clicked, this, [this, mode = m.mode] { setMode(mode); });
        h->addWidget(b);
        m_buttons[static_cast<int>(m.mode)] = b;
    }
    h->addSpacing(12);
    m_wireButton = new QToolButton(bar);
    m_wireButton->setObjectName(QStringLiteral("wireframe"));
    m_wireButton->setText(tr("Wireframe"));
    m_wireButton->setCheckable(true);
    m_wireButton->setToolTip(tr("Grid lines on the 3D surface (off by default above 60 × 60 "
                                "points, where they hide the colours)"));
    connect(m_wireButton, &QToolButton::toggled, this, &SurfaceView::setWireframe);
    h->addWidget(m_wireButton);
    m_resetButton = new QToolButton(bar);
    m_resetButton->setObjectName(QStringLiteral("resetView"));
    m_resetButton->setText(tr("Reset view"));
    m_resetButton->setToolTip(tr("The camera back to its starting position and zoom"));
    connect(m_resetButton, &QToolButton::clicked, this, &SurfaceView::resetView);
    h->addWidget(m_resetButton);
    h->addStretch(1);
    if (!m_3d) bar->setToolTip(tr("OpenGL is not available here: only the 2D map can be shown."));
    return bar;
}

void SurfaceView::setMode(SurfaceMode mode) {
    if (!m_3d) mode = SurfaceMode::Map;
    m_mode = mode;
    if (m_3d && mode != SurfaceMode::Map) {
        Q3DSurface* g = m_3d->graph;
        g->setOrthoProjection(mode == SurfaceMode::Top);
        resetView();
    }
    showPage();
}

void SurfaceView::showPage() {
    m_buttons[static_cast<int>(m_mode)]->setChecked(true);
    const bool gl = m_3d && m_mode != SurfaceMode::Map;
    m_wireButton->setEnabled(gl);
    m_resetButton->setEnabled(gl);
    if (m_grid.empty())
        m_stack->setCurrentWidget(m_hint);
    else
        m_stack->setCurrentWidget(gl ? m_3d->container : static_cast<QWidget*>(m_map));
    // The map draws its own colour bar beside its axes.
    m_bar->setVisible(gl && !m_grid.empty());
}

bool SurfaceView::showsGL() const {
    return m_3d && m_stack->currentWidget() == m_3d->container;
}

} // namespace kinstab::ui
