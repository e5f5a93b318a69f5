// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The result charts docked under the centre (γc against A, the history, A_crit(f)) show the
// surface's and a record run's results. The other tabs (Teaching with its own traces, Numerics,
// Friction, Floors, Study) get their room: the charts hide while such a tab is in front and
// come back, as the user left them, when a tab that uses them is in front again.

#include <QObject>
#include <QPointer>

#include <functional>
#include <vector>

class QDockWidget;
class QTabWidget;

namespace kinstab::ui {

class TabDocks : public QObject {
public:
    // usesDocks(tab) says whether the centre tab at that index shows the charts.
    TabDocks(QTabWidget* centre, std::vector<QDockWidget*> docks,
             std::function<bool(int)> usesDocks, QObject* parent);
    // Shows again what this hid (before the window's layout is saved, so it is saved shown).
    void giveBack();

private:
    void tabChanged(int index);

    std::vector<QDockWidget*> m_docks;
    std::function<bool(int)> m_usesDocks;
    std::vector<QPointer<QDockWidget>> m_hidden; // hidden here, not by the user
};

} // namespace kinstab::ui
