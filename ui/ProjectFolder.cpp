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

} // namespace kinstab::ui
