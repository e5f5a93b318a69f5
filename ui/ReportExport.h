// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// File → Export report… in the GUI: asks which sections to print and for a file name, runs the
// report's analyses in a worker (busy dialog, cancellable) and writes the same PDF as `kinstab-cli
// report`.

#include "core/io/Project.h"
#include "report/SectionCatalog.h"

#include <QString>

class QWidget;

namespace kinstab::ui::report {

// projectPath: the file the project was opened from or saved to ("" when never saved). When
// the panels differ from that file, the title block hashes the project JSON as used instead,
// and says so. Returns the path written, or "" when cancelled or failed (after a message box).
QString exportReportDialog(QWidget* parent, const Project& project, const QString& projectPath);
// The same without the dialogs: writes to out. Returns out, or "" when cancelled or failed.
QString exportReportTo(QWidget* parent, const Project& project, const QString& projectPath,
                       const QString& out, const SectionSet& sections = defaultSections());

} // namespace kinstab::ui::report
