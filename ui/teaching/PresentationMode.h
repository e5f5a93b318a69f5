// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Presentation mode (F11) for a lecture hall: the window full screen showing only the Teaching
// view, docks, menus, tool and status bars hidden, the text scaled up to be read from the back
// of the room. Esc or F11 leaves and puts the window back as it was. The text scale chosen
// while presenting is remembered (QSettings) for the next time.

#include <QByteArray>
#include <QObject>

class QMainWindow;
class QMenu;
class QTabWidget;
class QWidget;

namespace kinstab::ui {

class TeachingView;

class PresentationMode : public QObject {
    Q_OBJECT
public:
    // The window, its central tabs and the teaching view (inside one of the tabs).
    PresentationMode(QMainWindow* window, QTabWidget* tabs, TeachingView* view);

    bool isActive() const { return m_active; }
    double presentationScale() const { return m_scale; }
    static constexpr double kDefaultScale = 2.0;

public slots:
    void enter();
    void leave();
    void toggle();

signals:
    void activeChanged(bool active);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    int teachingTab() const;

    QMainWindow* m_window;
    QTabWidget* m_tabs;
    TeachingView* m_view;
    bool m_active = false;
    double m_scale = kDefaultScale;
    // What leave() puts back.
    QByteArray m_dockState;
    QByteArray m_geometry;
    Qt::WindowStates m_windowState;
    int m_tabBefore = 0;
    QList<QWidget*> m_hidden;
};

// Adds View → Presentation mode (F11) to the window; the shortcut works with the menu bar
// hidden, as it is while presenting.
PresentationMode* installPresentationMode(QMainWindow* window, QMenu* viewMenu, QTabWidget* tabs,
                                          TeachingView* view);

} // namespace kinstab::ui
