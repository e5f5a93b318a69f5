// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// File → Open example: the projects shipped with the program. An example is copied, with the
// record files it names, from the built-in resources into the user's data folder and opened
// from there, so that Save never writes over a shipped file and relative record paths hold.

#include <QString>
#include <QStringList>

#include <functional>
#include <vector>

class QMenu;

namespace kinstab::ui {

struct ExampleProject {
    QString title;      // the menu entry
    QString resource;   // ":/examples/NAME.json"
    QStringList extras; // other resources it refers to (relative paths), copied beside it
};

const std::vector<ExampleProject>& exampleProjects();
// The example copied to dir (keeping resources' layout); its path, or an empty string and
// the reason in *error.
QString copyExample(const ExampleProject& e, const QString& dir, QString* error);
// Where examples are copied: the user's application data, with examples/ and records/ in it
// as in the resources.
QString exampleRoot();
// Adds "Open example" to menu; open is called with the copied project's path.
void addExampleMenu(QMenu* menu, const std::function<void(const QString&)>& open);

} // namespace kinstab::ui
