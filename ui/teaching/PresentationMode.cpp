// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/teaching/PresentationMode.h"

#include "ui/ScreenFit.h"
#include "ui/teaching/TeachingView.h"

#include <QAction>
#include <QApplication>
#include <QDockWidget>
#include <QKeyEvent>
#include <QMainWindow>
#include <QMenu>
#include <QMenuBar>
#include <QSettings>
#include <QStatusBar>
#include <QTabBar>
#include <QTabWidget>
#include <QToolBar>

namespace kinstab::ui {

namespace {
const char* const kScaleKey = "teaching/presentationFontScale";
}

PresentationMode::PresentationMode(QMainWindow* window, QTabWidget* tabs, TeachingView* view)
    : QObject(window), m_window(window), m_tabs(tabs), m_view(view) {
    setObjectName(QStringLiteral("presentationMode"));
    m_scale = QSettings().value(kScaleKey, kDefaultScale).toDouble();
    if (!(m_scale >= 0.5 && m_scale <= 4.0)) m_scale = kDefaultScale;
    connect(view, &TeachingView::fontScaleChanged, this, [this](double s) {
        if (!m_active) return;
        m_scale = s;
        QSettings().setValue(kScaleKey, s);
    });
}

int PresentationMode::teachingTab() const {
    for (int i = 0; i < m_tabs->count(); ++i)
        if (m_tabs->widget(i) == m_view || m_tabs->widget(i)->isAncestorOf(m_view)) return i;
    return m_tabs->currentIndex();
}

void PresentationMode::enter() {
    if (m_active) return;
    m_active = true;
    m_dockState = m_window->saveState();
    m_geometry = m_window->saveGeometry();
    m_windowState = m_window->windowState();
    m_tabBefore = m_tabs->currentIndex();
    m_hidden.clear();
    QList<QWidget*> chrome{m_window->menuBar(), m_window->statusBar(), m_tabs->tabBar()};
    for (QDockWidget* d : m_window->findChildren<QDockWidget*>())
        chrome << d;
    for (QToolBar* t : m_window->findChildren<QToolBar*>())
        chrome << t;
    for (QWidget* w : chrome)
        if (w->isVisible()) {
            m_hidden << w;
            w->hide();
        }
    m_tabs->setCurrentIndex(teachingTab());
    m_view->setFontScale(m_scale);
    m_window->setWindowState(m_windowState | Qt::WindowFullScreen);
    qApp->installEventFilter(this);
    m_view->setFocus();
    emit activeChanged(true);
}

void PresentationMode::leave() {
    if (!m_active) return;
    m_active = false;
    qApp->removeEventFilter(this);
    m_view->setFontScale(1.0);
    m_window->setWindowState(m_windowState & ~Qt::WindowFullScreen);
    for (QWidget* w : m_hidden)
        w->show();
    m_hidden.clear();
    m_window->restoreState(m_dockState);
    m_window->restoreGeometry(m_geometry);
    // restoreGeometry keeps room for a title bar of the style's height above the window, which
    // on a screen just the window's height pushed its bottom (the status bar) off the screen.
    fitToScreen(m_window, m_window->size());
    m_tabs->setCurrentIndex(m_tabBefore);
    emit activeChanged(false);
}

void PresentationMode::toggle() {
    m_active ? leave() : enter();
}

// Esc leaves wherever the focus is, before any Esc shortcut (Cancel) can take it.
bool PresentationMode::eventFilter(QObject* watched, QEvent* event) {
    if (m_active &&
        (event->type() == QEvent::ShortcutOverride || event->type() == QEvent::KeyPress)) {
        auto* key = static_cast<QKeyEvent*>(event);
        if (key->key() == Qt::Key_Escape && key->modifiers() == Qt::NoModifier) {
            if (event->type() == QEvent::ShortcutOverride) {
                event->accept(); // a key press follows instead of the shortcut
            } else {
                leave();
            }
            return true;
        }
    }
    return QObject::eventFilter(watched, event);
}

PresentationMode* installPresentationMode(QMainWindow* window, QMenu* viewMenu, QTabWidget* tabs,
                                          TeachingView* view) {
    auto* mode = new PresentationMode(window, tabs, view);
    QAction* a = viewMenu->addAction(PresentationMode::tr("&Presentation mode"));
    a->setObjectName(QStringLiteral("presentationAction"));
    a->setShortcut(Qt::Key_F11);
    a->setCheckable(true);
    a->setToolTip(PresentationMode::tr("Full screen with the Teaching view alone and large text, "
                                       "for a projector (F11; Esc leaves)"));
    window->addAction(a); // keeps F11 working while the menu bar is hidden
    QObject::connect(a, &QAction::triggered, mode, &PresentationMode::toggle);
    QObject::connect(mode, &PresentationMode::activeChanged, a, &QAction::setChecked);
    viewMenu->addSeparator();
    return mode;
}

} // namespace kinstab::ui
