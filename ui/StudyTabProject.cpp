// SPDX-License-Identifier: GPL-3.0-or-later
// StudyTab, continued: the project's study - shown when a project is opened, with its results
// read back; made the project's by "Use in project"; results marked stale when the fields change.

#include "core/io/StudyResults.h"
#include "core/io/StudySpecJson.h"
#include "core/study/StudyRecordMetrics.h"
#include "core/study/StudyRecords.h"
#include "core/study/StudyRowsMatch.h"
#include "ui/FragilityChart.h"
#include "ui/RiskPanel.h"
#include "ui/StudyTab.h"
#include "ui/StudyTabOutcome.h"

#include <QChartView>
#include <QComboBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFileInfo>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>

namespace kinstab::ui {

bool StudyTab::useInProject(const QString& savePath) {
    const std::string text = studyJson();
    if (m_studyFile.isEmpty() || text != m_openedText) {
        if (savePath.isEmpty()) {
            m_status->setText(tr("Save the study to a file first: the project names a file."));
            return false;
        }
        try {
            (void)studyFromJsonText(text, "");
        } catch (const StudyError& e) {
            m_status->setText(tr("Cannot use the study: %1").arg(e.what()));
            return false;
        }
        if (!save(savePath, text + "\n")) return false;
        m_studyFile = savePath;
        m_openedText = text;
    }
    const QString results = currentResultsFile();
    emit studyChosen(QFileInfo(m_studyFile).absoluteFilePath(), results);
    QString note = tr("The project's study is now %1").arg(m_studyFile);
    if (!results.isEmpty())
        note += tr(", with its results %1").arg(results);
    else if (resultsStale())
        note += tr(", without the results shown (they are for other parameters)");
    else if (!m_parsed.empty())
        note += tr(", without the results shown (their file could not be written)");
    m_status->setText(note + tr("; save the project to keep it."));
    return true;
}

QString StudyTab::currentResultsFile() {
    if (m_parsed.empty() || resultsStale()) return {};
    if (!m_resultsFile.isEmpty()) return QFileInfo(m_resultsFile).absoluteFilePath();
    const QFileInfo spec(m_studyFile);
    const QString path = spec.absoluteDir().filePath(spec.completeBaseName() + ".jsonl");
    if (!save(path, m_rows)) return {};
    m_resultsFile = path;
    return path;
}

void StudyTab::clear() {
    m_job.discard();         // a job still running belongs to what is cleared
    m_job.waitForFinished(); // within one case per thread
    m_run->setEnabled(true);
    m_cancel->setEnabled(false);
    m_base = nlohmann::json::object();
    m_studyFile.clear();
    m_openedText.clear();
    m_openedRecords = nlohmann::json();
    m_openedRecordFields.clear();
    setRecordsFolder(QString(), "*.AT2", "*UP*, *DWN*");
    m_measure->setCurrentText("pga");
    m_saPeriod->setValue(1.0);
    setLists("0.4,0.6", "0.099", QString());
    setSearch(3.0, 0.02);
    m_rows.clear();
    m_parsed.clear();
    m_fragility.clear();
    m_metrics.clear();
    m_resultsSpec.clear();
    m_resultsFile.clear();
    fillFragilityChart(m_chart->chart(), m_fragility);
    fillTable();
    m_risk->clear();
    m_export->setEnabled(false);
    m_progress->setValue(0);
    m_status->clear();
    updateStaleness();
}

void StudyTab::showProjectStudy(const std::optional<ProjectStudy>& study,
                                const QString& projectDir) {
    clear();
    if (!study) return;
    m_risk->setHazard(study->hazard);
    const QString spec = QString::fromStdString(study->spec);
    if (!openStudy(spec)) return; // the message says why
    QString results = QString::fromStdString(study->results);
    if (results.isEmpty()) { // kinstab-cli study -o NAME.jsonl beside the project or the study
        const QString name = QFileInfo(spec).completeBaseName() + ".jsonl";
        for (const QString& dir : {projectDir, QFileInfo(spec).absolutePath()})
            if (!dir.isEmpty() && QFileInfo::exists(QDir(dir).filePath(name))) {
                results = QDir(dir).filePath(name);
                break;
            }
    }
    if (results.isEmpty()) return;
    const std::string fields = studyJson();
    startJob(
        [spec, results, fields](JobContext&) {
            StudyOutcome o = readStudyResults(spec, results);
            o.spec = fields;
            return o;
        },
        tr("Reading the study's results %1…").arg(results));
}

bool StudyTab::resultsStale() const {
    return !m_parsed.empty() && studyJson() != m_resultsSpec;
}

void StudyTab::updateStaleness() {
    m_stale->setVisible(resultsStale());
}

StudyOutcome readStudyResults(const QString& specPath, const QString& rowsPath) {
    StudyOutcome o;
    o.file = rowsPath;
    try {
        StudySpec spec = loadStudy(specPath.toStdString());
        hashStudyRecords(spec); // the rows' fingerprint is checked against the records' bytes
        std::string text;       // kept for export and "Use in project": the file is read once
        std::vector<StudyRow> rows = readStudyRows(rowsPath.toStdString(), &text);
        const std::string dir = QFileInfo(specPath).absolutePath().toStdString();
        if (const std::string m = studyRowsMismatch(spec, dir, rows); !m.empty()) {
            o.notice = QObject::tr("The results %1 are not shown: they are not the study's "
                                   "(%2). Run the study again.")
                           .arg(rowsPath, QString::fromStdString(m));
            return o;
        }
        o.rows = std::move(text);
        o.fragility = studyFragility(rows, {});
        o.parsed = std::move(rows);
        o.metrics = studyRecordMetrics(spec); // reads the records: the rows did not need them
    } catch (const std::exception& e) {
        o.notice = QObject::tr("The results %1 are not shown: %2")
                       .arg(rowsPath, QString::fromStdString(e.what()));
    }
    return o;
}

} // namespace kinstab::ui
