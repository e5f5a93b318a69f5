// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/TabDocks.h"

#include <QDockWidget>
#include <QTabWidget>

namespace kinstab::ui {

TabDocks::TabDocks(QTabWidget* centre, std::vector<QDockWidget*> docks,
                   std::function<bool(int)> usesDocks, QObject* parent)
    : QObject(parent), m_docks(std::move(docks)), m_usesDocks(std::move(usesDocks)) {
    connect(centre, &QTabWidget::currentChanged, this, &TabDocks::tabChanged);
}

void TabDocks::giveBack() {
    for (const QPointer<QDockWidget>& d : m_hidden)
        if (d) d->show();
    m_hidden.clear();
}

void TabDocks::tabChanged(int index) {
    if (m_usesDocks(index)) {
        giveBack();
        return;
    }
    // Floating charts are out of the centre's way; closed ones stay closed.
    for (QDockWidget* d : m_docks)
        if (d->isVisible() && !d->isFloating()) {
            d->hide();
            m_hidden.emplace_back(d);
        }
}

} // namespace kinstab::ui
