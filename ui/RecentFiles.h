// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The File > Recent submenu, kept in QSettings (most recent first, at most maxFiles).

#include <QMenu>

namespace kinstab::ui {

class RecentFiles : public QMenu {
    Q_OBJECT
public:
    explicit RecentFiles(const QString& title, QWidget* parent = nullptr);

    void add(const QString& path);
    QStringList files() const;

    static constexpr int maxFiles = 8;

signals:
    void openRequested(const QString& path);

private:
    void rebuild();
};

} // namespace kinstab::ui
