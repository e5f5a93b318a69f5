// SPDX-License-Identifier: GPL-3.0-or-later
// StudyTab, continued: the run - the job off the GUI thread (ui/BackgroundJob.h) that runs every
// case and fits the fragility, and its outcome shown in the chart, the tables and the risk.

#include "core/io/StudyRowJson.h"
#include "core/io/StudySpecJson.h"
#include "core/study/CpuAffinity.h"
#include "core/study/StudyRecordMetrics.h"
#include "core/study/StudyRecords.h"
#include "core/study/StudyRunner.h"
#include "ui/FragilityChart.h"
#include "ui/RiskPanel.h"
#include "ui/StudyTab.h"
#include "ui/StudyTabOutcome.h"
#include "ui/StudyTables.h"

#include <QChartView>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>

namespace kinstab::ui {

bool StudyTab::isRunning() const {
    return m_job.isRunning();
}

void StudyTab::run() {
    if (isRunning()) return;
    const std::string json = studyJson();
    startJob(
        [json](JobContext& job) {
            job.control.onProgress = [&job](std::size_t done, std::size_t total) {
                job.done = done;
                job.total = total;
            };
            StudyOutcome o = runStudyJob(json, &job.control);
            o.spec = json;
            return o;
        },
        tr("Running the study…"));
}

void StudyTab::startJob(std::function<StudyOutcome(JobContext&)> job, const QString& status) {
    m_job.start<StudyOutcome>(std::move(job), [this](StudyOutcome o) { onDelivered(o); });
    m_status->setText(status);
    m_progress->setValue(0);
    m_run->setEnabled(false);
    m_cancel->setEnabled(true);
}

void StudyTab::cancel() {
    m_job.cancel();
}

void StudyTab::onDelivered(const StudyOutcome& o) {
    if (!o.error.empty()) {
        m_status->setText(tr("Cannot run the study: %1").arg(QString::fromStdString(o.error)));
    } else if (!o.notice.isEmpty()) {
        m_status->setText(o.notice);
    } else if (o.cancelled) {
        m_status->setText(tr("Cancelled: nothing is shown of a partial study."));
    } else {
        showResults(o);
    }
}

void StudyTab::showResults(const StudyOutcome& o) {
    m_rows = o.rows;
    m_parsed = o.parsed;
    m_fragility = o.fragility;
    m_metrics = o.metrics;
    m_resultsSpec = o.spec;
    m_resultsFile = o.file;
    fillFragilityChart(m_chart->chart(), m_fragility);
    fillTable();
    m_risk->setRows(m_parsed);
    m_export->setEnabled(true);
    const int done = static_cast<int>(m_parsed.size());
    if (done > 0) { // read back, not run: the bar shows the study complete all the same
        m_progress->setRange(0, done);
        m_progress->setValue(done);
    }
    QString text = tr("%1 cases, %2 parameter sets.").arg(m_parsed.size()).arg(m_fragility.size());
    if (!o.file.isEmpty()) text += tr(" Read from %1.").arg(o.file);
    m_status->setText(text);
    updateStaleness();
}

void StudyTab::fillTable() {
    fillStudySetTable(m_sets, m_fragility);
    fillStudyCaseTable(m_table, m_parsed, m_metrics);
}

StudyOutcome runStudyJob(const std::string& json, SweepControl* control) {
    StudyOutcome o;
    try {
        StudySpec spec = studyFromJsonText(json, "");
        loadStudyRecords(spec); // each record read once, for every case of the study
        StudyRunOptions options;
        options.threads = allowedCpuCount();
        options.control = control;
        o.parsed = runStudyRows(spec, options);
        o.cancelled = control->isCancelled();
        if (o.cancelled) return o;
        o.rows = studyRowsText(o.parsed); // what File → Save results writes
        o.fragility = studyFragility(o.parsed, {});
        o.metrics = studyRecordMetrics(spec);
    } catch (const StudyError& e) {
        o.error = e.what();
    }
    return o;
}

} // namespace kinstab::ui
