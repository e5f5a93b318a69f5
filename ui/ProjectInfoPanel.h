// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// File → Project information…: who issues the report and for whom (core/io/ProjectInfo.h) —
// engineer, registration, firm, client, project number, site, prepared/checked by — and the
// revision history, printed on the report's title block, signature block and revision table.

#include "core/io/ProjectInfo.h"

#include <QWidget>

class QLabel;
class QTableWidget;

namespace kinstab::ui {

class TextField;

class ProjectInfoPanel : public QWidget {
    Q_OBJECT
public:
    explicit ProjectInfoPanel(QWidget* parent = nullptr);

    void setInfo(const ProjectInfo& info);
    ProjectInfo info() const;

    // A dialog around the panel. OK checks the entries (validateProjectInfo) and says which field
    // is wrong without closing; returns true and updates info when accepted.
    static bool editInDialog(QWidget* parent, ProjectInfo& info);

    // What is wrong with the entries, "" when nothing (validateProjectInfo's message).
    QString problem() const;

private:
    void addRevision();
    void checkRevisions(); // the revisions' problem, shown under their table

    std::vector<std::pair<TextField*, std::string ProjectInfo::*>> fields_;
    QTableWidget* revisions_ = nullptr;
    QLabel* revisionsError_ = nullptr;
};

} // namespace kinstab::ui
