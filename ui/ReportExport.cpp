// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/ReportExport.h"

#include "core/io/AtomicFile.h"

#include "report/ReportWriter.h"
#include "ui/ProjectFolder.h"
#include "ui/ReportSectionsDialog.h"

#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QLocale>
#include <QMessageBox>
#include <QProgressDialog>

#include <memory>

namespace kinstab::ui {

using namespace kinstab::report;

struct AnalysisRun {
    std::optional<ReportAnalysis> analysis;
    QString error;
    bool cancelled = false;
};

namespace {

// The saved file when the panels still match it; otherwise the project JSON as used.
ReportSource sourceFor(const Project& p, const QString& path, const SectionSet& sections) {
    ReportSource s;
    s.sections = sections;
    s.project = p;
    const std::string used = projectToJson(p).dump(2);
    if (!path.isEmpty()) {
        try {
            if (projectToJson(loadProject(path.toStdString())).dump(2) == used) {
                QFile f(path);
                if (f.open(QIODevice::ReadOnly)) {
                    s.fileName = path;
                    s.fileContents = f.readAll();
                    return s;
                }
            }
        } catch (const ProjectError&) {
            // The file changed or vanished since: report the inputs as used.
        }
    }
    s.fileName =
        (path.isEmpty() ? QStringLiteral("unsaved project")
                        : QFileInfo(path).fileName() + QStringLiteral(" + unsaved changes")) +
        QStringLiteral(" (hash of the project JSON as used)");
    s.fileContents = QByteArray::fromStdString(used);
    return s;
}

} // namespace

void exportReportDialog(QWidget* parent, const Project& project, const QString& projectPath,
                        const std::function<void(const QString&)>& written) {
    SectionSet sections = defaultSections();
    if (!ReportSectionsDialog::choose(parent, sections)) return;
    const QString base = inProjectFolder(
        projectPath, projectPath.isEmpty() ? QStringLiteral("report.pdf")
                                           : QFileInfo(projectPath).completeBaseName() + ".pdf");
    const QString out = QFileDialog::getSaveFileName(parent, QObject::tr("Export design report"),
                                                     base, QObject::tr("PDF (*.pdf)"));
    if (out.isEmpty()) return;
    ReportExport* e = exportReportTo(parent, project, projectPath, out, sections);
    QObject::connect(e, &ReportExport::done, parent, [written](const QString& path) {
        if (!path.isEmpty()) written(path);
    });
}

ReportExport* exportReportTo(QWidget* parent, const Project& project, const QString& projectPath,
                             const QString& out, const SectionSet& sections) {
    return new ReportExport(parent, project, projectPath, out, sections);
}

ReportExport::ReportExport(QWidget* parent, const Project& project, const QString& projectPath,
                           const QString& out, const SectionSet& sections)
    : QObject(parent), m_parent(parent), m_project(project), m_projectPath(projectPath), m_out(out),
      m_sections(sections), m_job(this) {
    m_busy = new QProgressDialog(QObject::tr("Computing the report's sweeps and design check…"),
                                 QObject::tr("Cancel"), 0, 0, parent);
    m_busy->setWindowModality(Qt::WindowModal);
    m_busy->setMinimumDuration(300);
    connect(m_busy, &QProgressDialog::canceled, &m_job, &BackgroundJob::cancel);
    m_job.start<AnalysisRun>(
        [project](JobContext& job) {
            AnalysisRun r;
            try {
                auto& analysis = static_cast<AnalysisJobContext&>(job).analysis;
                r.analysis = computeReportAnalysis(project, {}, &analysis);
            } catch (const std::exception& e) {
                r.error = QString::fromUtf8(e.what());
            }
            r.cancelled = job.isCancelled();
            return r;
        },
        [this](const AnalysisRun& run) { write(run); }, std::make_shared<AnalysisJobContext>());
}

ReportExport::~ReportExport() {
    delete m_busy; // (null when its parent went first)
}

void ReportExport::write(const AnalysisRun& run) {
    if (m_busy) m_busy->reset();
    if (run.cancelled) return finish({});
    if (!run.analysis) {
        QMessageBox::warning(m_parent, QObject::tr("Export design report"), run.error);
        return finish({});
    }
    const PaperSize paper = QLocale().measurementSystem() == QLocale::ImperialUSSystem
                                ? PaperSize::Letter
                                : PaperSize::A4;
    try {
        writeReport(sourceFor(m_project, m_projectPath, m_sections), *run.analysis, m_out, paper);
    } catch (const ReportError& e) {
        QMessageBox::warning(m_parent, QObject::tr("Export design report"),
                             m_out + ": " + QString::fromUtf8(e.what()));
        return finish({});
    } catch (const kinstab::WriteError& e) { // names the file and the reason
        QMessageBox::warning(m_parent, QObject::tr("Export design report"),
                             QString::fromUtf8(e.what()));
        return finish({});
    }
    finish(m_out);
}

void ReportExport::finish(const QString& path) {
    emit done(path);
    deleteLater();
}

} // namespace kinstab::ui
