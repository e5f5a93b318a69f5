// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// File → Export report… in the GUI: asks which sections to print and for a file name, runs the
// report's analyses on a
// BackgroundJob (busy dialog, cancellable, the window stays live) and then writes the same PDF
// as `kinstab-cli report`.

#include "core/io/Project.h"
#include "report/SectionCatalog.h"
#include "ui/BackgroundJob.h"

#include <QObject>
#include <QPointer>
#include <QString>

class QProgressDialog;
class QWidget;

namespace kinstab::ui {

struct AnalysisRun;

// One export in flight. A child of the window that started it, so closing the window cancels it
// and waits; it deletes itself after done().
class ReportExport : public QObject {
    Q_OBJECT
public:
    // projectPath: the file the project was opened from or saved to ("" when never saved). When
    // the panels differ from that file, the title block hashes the project JSON as used instead,
    // and says so.
    ReportExport(QWidget* parent, const Project& project, const QString& projectPath,
                 const QString& out, const report::SectionSet& sections);
    ~ReportExport() override;

signals:
    // The path written, or "" when cancelled or failed (after a message box).
    void done(const QString& path);

private:
    void write(const AnalysisRun& run);
    void finish(const QString& path);

    QWidget* m_parent;
    Project m_project;
    QString m_projectPath;
    QString m_out;
    report::SectionSet m_sections;
    QPointer<QProgressDialog> m_busy;
    BackgroundJob m_job;
};

// Asks for the sections and a file name, then starts an export; written(path) follows when it is on
// disk.
void exportReportDialog(QWidget* parent, const Project& project, const QString& projectPath,
                        const std::function<void(const QString&)>& written);
// The same without the file dialog: starts writing out and returns the export (watch done()).
ReportExport* exportReportTo(QWidget* parent, const Project& project, const QString& projectPath,
                             const QString& out,
                             const report::SectionSet& sections = report::defaultSections());

} // namespace kinstab::ui
