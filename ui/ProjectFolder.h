// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Where the Open, Save as and Export dialogs start: the open project's folder, so that a report
// or a chart lands beside the project it comes from rather than in whatever folder the program
// was started from.

#include <QString>

namespace kinstab::ui {

// fileName in the folder of projectPath; in the user's documents folder while the project has
// not been saved (an empty fileName gives the folder itself).
QString inProjectFolder(const QString& projectPath, const QString& fileName = {});

// The open project's file, for dialogs of views that do not hold it (the main window sets it
// when a project is opened, saved or started).
void setOpenProjectPath(const QString& path);
// fileName in the open project's folder (the documents folder for an unsaved project).
QString inOpenProjectFolder(const QString& fileName = {});

} // namespace kinstab::ui
