// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/HelpMenu.h"

#include "ui/AboutBox.h"
#include "ui/HelpWindow.h"

#include <QApplication>
#include <QDockWidget>
#include <QMainWindow>
#include <QMenuBar>
#include <QTabWidget>

#include <map>

namespace kinstab::ui {

namespace {

const QString kIntroduction = QStringLiteral("Your first design check in five steps");

// Dock and tab titles of the main window → headings of docs/user-guide.md.
QString sectionForTitle(const QString& title) {
    static const std::map<QString, QString> table = {
        {QStringLiteral("Building"), QStringLiteral("Building")},
        {QStringLiteral("Codes"), QStringLiteral("Codes")},
        {QStringLiteral("Slab"), QStringLiteral("Slab and walls")},
        {QStringLiteral("Model"), QStringLiteral("Model")},
        {QStringLiteral("Motion"), QStringLiteral("Excitation")},
        {QStringLiteral("Grid"), QStringLiteral("Grid")},
        {QStringLiteral("Verdict"), QStringLiteral("Verdict")},
        {QStringLiteral("γc, τc against A"), QStringLiteral("The charts")},
        {QStringLiteral("History"), QStringLiteral("The charts")},
        {QStringLiteral("A_crit(f)"), QStringLiteral("The charts")},
        {QStringLiteral("γc surface"), QStringLiteral("Reading a γc surface")},
        // The first tab while the free-standing block is the model: its map is told there.
        {QStringLiteral("Overturning map"), QStringLiteral("Model")},
        {QStringLiteral("Teaching"), QStringLiteral("The teaching view")},
        {QStringLiteral("Records"), QStringLiteral("Records")},
        {QStringLiteral("Numerics"), QStringLiteral("Numerics")},
        {QStringLiteral("Friction"), QStringLiteral("Friction")},
    };
    const auto it = table.find(title);
    return it == table.end() ? kIntroduction : it->second;
}

} // namespace

QString helpSectionFor(const QWidget* focus) {
    for (const QWidget* w = focus; w; w = w->parentWidget()) {
        if (const auto* dock = qobject_cast<const QDockWidget*>(w))
            return sectionForTitle(dock->windowTitle());
        if (const auto* tabs = qobject_cast<const QTabWidget*>(w)) {
            for (int i = 0; i < tabs->count(); ++i) {
                const QWidget* page = tabs->widget(i);
                if (page == focus || page->isAncestorOf(focus))
                    return sectionForTitle(tabs->tabText(i));
            }
        }
    }
    return kIntroduction;
}

QWidget* showUserGuide(QMainWindow* window, const QString& section) {
    auto* help = window->findChild<HelpWindow*>(QStringLiteral("helpWindow"));
    if (!help) help = new HelpWindow(window);
    help->show();
    help->raise();
    help->activateWindow();
    help->showSection(section);
    return help;
}

void installHelpMenu(QMainWindow* window) {
    QMenu* menu = window->menuBar()->addMenu(QObject::tr("&Help"));
    QAction* guide = menu->addAction(QObject::tr("&User guide"), window, [window] {
        showUserGuide(window, helpSectionFor(QApplication::focusWidget()));
    });
    guide->setObjectName(QStringLiteral("userGuideAction"));
    guide->setShortcut(QKeySequence::HelpContents);
    guide->setShortcutContext(Qt::ApplicationShortcut);
    QAction* about = menu->addAction(QObject::tr("&About kinstab"), window, [window] {
        AboutBox box(window);
        box.exec();
    });
    about->setObjectName(QStringLiteral("aboutAction"));
    about->setMenuRole(QAction::AboutRole);
}

} // namespace kinstab::ui
