// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/ProjectFolder.h"

#include <QDir>
#include <QFileInfo>
#include <QStandardPaths>

namespace kinstab::ui {

QString inProjectFolder(const QString& projectPath, const QString& fileName) {
    QString folder = projectPath.isEmpty() ? QString() : QFileInfo(projectPath).absolutePath();
    if (folder.isEmpty() || !QFileInfo(folder).isDir())
        folder = QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
    if (folder.isEmpty() || !QFileInfo(folder).isDir()) folder = QDir::homePath();
    return fileName.isEmpty() ? folder : QDir(folder).filePath(fileName);
}

namespace {
QString& openProjectPath() {
    static QString path; // the GUI thread's only
    return path;
}
} // namespace

void setOpenProjectPath(const QString& path) {
    openProjectPath() = path;
}

QString inOpenProjectFolder(const QString& fileName) {
    return inProjectFolder(openProjectPath(), fileName);
}

} // namespace kinstab::ui
