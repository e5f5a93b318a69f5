// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/RecentFiles.h"

#include <QFileInfo>
#include <QSettings>

namespace kinstab::ui {

namespace {
const QString key = QStringLiteral("project/recentFiles");
}

RecentFiles::RecentFiles(const QString& title, QWidget* parent) : QMenu(title, parent) {
    rebuild();
}

QStringList RecentFiles::files() const {
    return QSettings().value(key).toStringList();
}

void RecentFiles::add(const QString& path) {
    const QString abs = QFileInfo(path).absoluteFilePath();
    QStringList list = files();
    list.removeAll(abs);
    list.prepend(abs);
    while (list.size() > maxFiles)
        list.removeLast();
    QSettings().setValue(key, list);
    rebuild();
}

void RecentFiles::rebuild() {
    clear();
    const QStringList list = files();
    for (int i = 0; i < list.size(); ++i) {
        const QString path = list[i];
        QAction* a = addAction(QStringLiteral("&%1 %2").arg(i + 1).arg(QFileInfo(path).fileName()));
        a->setToolTip(path);
        a->setStatusTip(path);
        connect(a, &QAction::triggered, this, [this, path] { emit openRequested(path); });
    }
    setEnabled(!list.isEmpty());
}

} // namespace kinstab::ui
