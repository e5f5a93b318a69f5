// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/ReportExport.h"

#include "core/io/AtomicFile.h"

#include "report/ReportWriter.h"
#include "ui/ReportSectionsDialog.h"

#include <QEventLoop>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QFutureWatcher>
#include <QLocale>
#include <QMessageBox>
#include <QProgressDialog>
#include <QtConcurrent/QtConcurrentRun>

#include <memory>

namespace kinstab::ui::report {

namespace {

struct AnalysisRun {
    std::optional<ReportAnalysis> analysis;
    QString error;
};

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

QString exportReportDialog(QWidget* parent, const Project& project, const QString& projectPath) {
    SectionSet sections = defaultSections();
    if (!ReportSectionsDialog::choose(parent, sections)) return {};
    const QString base = projectPath.isEmpty() ? QStringLiteral("report.pdf")
                                               : QFileInfo(projectPath).completeBaseName() + ".pdf";
    const QString out = QFileDialog::getSaveFileName(parent, QObject::tr("Export design report"),
                                                     base, QObject::tr("PDF (*.pdf)"));
    if (out.isEmpty()) return {};
    return exportReportTo(parent, project, projectPath, out, sections);
}

QString exportReportTo(QWidget* parent, const Project& project, const QString& projectPath,
                       const QString& out, const SectionSet& sections) {
    auto control = std::make_shared<SweepControl>();
    QFutureWatcher<AnalysisRun> watcher;
    QEventLoop loop;
    QObject::connect(&watcher, &QFutureWatcherBase::finished, &loop, &QEventLoop::quit);
    QProgressDialog busy(QObject::tr("Computing the report's sweeps and design check…"),
                         QObject::tr("Cancel"), 0, 0, parent);
    busy.setWindowModality(Qt::WindowModal);
    busy.setMinimumDuration(300);
    QObject::connect(&busy, &QProgressDialog::canceled, &busy, [control] { control->cancel(); });
    watcher.setFuture(QtConcurrent::run([project, control] {
        AnalysisRun r;
        try {
            r.analysis = computeReportAnalysis(project, {}, control.get());
        } catch (const std::exception& e) {
            r.error = QString::fromUtf8(e.what());
        }
        return r;
    }));
    loop.exec();
    busy.reset();
    const AnalysisRun run = watcher.result();
    if (control->isCancelled()) return {};
    if (!run.analysis) {
        QMessageBox::warning(parent, QObject::tr("Export design report"), run.error);
        return {};
    }
    const PaperSize paper = QLocale().measurementSystem() == QLocale::ImperialUSSystem
                                ? PaperSize::Letter
                                : PaperSize::A4;
    try {
        writeReport(sourceFor(project, projectPath, sections), *run.analysis, out, paper);
    } catch (const ReportError& e) {
        QMessageBox::warning(parent, QObject::tr("Export design report"),
                             out + ": " + QString::fromUtf8(e.what()));
        return {};
    } catch (const kinstab::WriteError& e) { // names the file and the reason
        QMessageBox::warning(parent, QObject::tr("Export design report"),
                             QString::fromUtf8(e.what()));
        return {};
    }
    return out;
}

} // namespace kinstab::ui::report
