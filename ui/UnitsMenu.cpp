// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/UnitsMenu.h"

#include "ui/NumberField.h"

#include <QAction>
#include <QActionGroup>
#include <QCoreApplication>
#include <QMenu>
#include <QWidget>

namespace kinstab::ui {

void showUnitSystem(QWidget* root, UnitSystem s) {
    const QString name =
        s == UnitSystem::SI ? QStringLiteral("unitsSI") : QStringLiteral("unitsUS");
    if (auto* a = root->findChild<QAction*>(name)) a->setChecked(true);
}

void applyUnitSystem(QWidget* root, UnitSystem s) {
    for (NumberField* f : root->findChildren<NumberField*>())
        f->setUnitSystem(s);
}

void installUnitsMenu(QMenu* viewMenu, QWidget* root, std::function<void(UnitSystem)> also) {
    QMenu* menu = viewMenu->addMenu(QCoreApplication::translate("Units", "&Units"));
    auto* group = new QActionGroup(menu);
    const UnitSystem saved = savedUnitSystem();
    for (UnitSystem s : {UnitSystem::SI, UnitSystem::US}) {
        QAction* a = menu->addAction(unitSystemTitle(s));
        a->setObjectName(s == UnitSystem::SI ? QStringLiteral("unitsSI")
                                             : QStringLiteral("unitsUS"));
        a->setCheckable(true);
        a->setChecked(s == saved);
        group->addAction(a);
        QObject::connect(a, &QAction::triggered, root, [root, s, also] {
            applyUnitSystem(root, s);
            if (also) also(s);
            saveUnitSystem(s);
        });
    }
    applyUnitSystem(root, saved);
    if (also) also(saved);
}

} // namespace kinstab::ui
