// SPDX-License-Identifier: GPL-3.0-or-later
// StudyTab (ui/StudyTab.h): its construction, the fields' setters and the export. The rest:
// StudyTabFile (the study file and the fields), StudyTabRun (the run and its results),
// StudyTabProject (the project's study), StudyTables (the set and case tables).
#include "ui/StudyTab.h"

#include "core/io/AtomicFile.h"
#include "core/io/FragilityText.h"
#include "core/io/JsonText.h"
#include "ui/ProjectFolder.h"
#include "ui/RiskPanel.h"
#include "ui/StaleFrame.h"
#include "ui/StudyTables.h"

#include <nlohmann/json.hpp>

#include <QChart>
#include <QChartView>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QRegularExpression>
#include <QSplitter>
#include <QTabWidget>
#include <QTableWidget>
#include <QVBoxLayout>

namespace kinstab::ui {

namespace {

QDoubleSpinBox* spin(double lo, double hi, double value, int decimals, const QString& suffix) {
    auto* s = new QDoubleSpinBox;
    s->setRange(lo, hi);
    s->setDecimals(decimals);
    s->setValue(value);
    s->setSuffix(suffix);
    return s;
}

} // namespace

StudyTab::StudyTab(QWidget* parent)
    : QWidget(parent), m_folder(new QLineEdit(this)), m_include(new QLineEdit(this)),
      m_exclude(new QLineEdit(this)), m_measure(new QComboBox(this)),
      m_saPeriod(spin(0.01, 20, 1.0, 2, " s")), m_mu(new QLineEdit(this)),
      m_tstar(new QLineEdit(this)), m_floors(new QLineEdit(this)),
      m_maxG(spin(0.01, 100, 3.0, 2, " g")), m_step(spin(0.001, 1, 0.02, 3, " g")),
      m_run(new QPushButton(tr("Run study"), this)), m_cancel(new QPushButton(tr("Cancel"), this)),
      m_export(new QPushButton(tr("Export…"), this)), m_progress(new QProgressBar(this)),
      m_status(new QLabel(this)),
      m_stale(
          new QLabel(tr("The results below are for the previous parameters — run again."), this)),
      m_chart(new QChartView(new QChart, this)), m_risk(new RiskPanel(this)),
      m_sets(makeStudySetTable(this)), m_table(makeStudyCaseTable(this)), m_job(this) {
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(buildFileRow());
    layout->addLayout(buildForm());
    layout->addLayout(buildRunBar());
    layout->addWidget(m_status);
    layout->addWidget(m_stale);
    layout->addWidget(buildResults(), 1);
    connectFields();
    connect(&m_job, &BackgroundJob::progress, this, [this](qint64 done, qint64 total) {
        if (total <= 0) return; // not known yet
        m_progress->setRange(0, static_cast<int>(total));
        m_progress->setValue(static_cast<int>(done));
    });
    connect(&m_job, &BackgroundJob::failed, this,
            [this](const QString& e) { m_status->setText(tr("Cannot run the study: %1").arg(e)); });
    connect(&m_job, &BackgroundJob::ended, this, [this] {
        m_run->setEnabled(true);
        m_cancel->setEnabled(false);
        emit finished();
    });
    clear();
}

// Open a study file, or make the fields the project's study.
QLayout* StudyTab::buildFileRow() {
    auto* open = new QPushButton(tr("Open study…"), this);
    auto* use = new QPushButton(tr("Use in project"), this);
    connect(open, &QPushButton::clicked, this, [this] {
        const QString f = QFileDialog::getOpenFileName(
            this, tr("Open study"), m_studyFile.isEmpty() ? inOpenProjectFolder() : m_studyFile,
            tr("Study files (*.json)"));
        if (!f.isEmpty()) openStudy(f);
    });
    connect(use, &QPushButton::clicked, this, [this] {
        QString f;
        if (m_studyFile.isEmpty() || studyJson() != m_openedText)
            f = QFileDialog::getSaveFileName(this, tr("Save the study for the project"),
                                             inOpenProjectFolder("study.json"),
                                             tr("Study files (*.json)"));
        if (!f.isEmpty() || !m_studyFile.isEmpty()) useInProject(f);
    });
    auto* row = new QHBoxLayout;
    row->addWidget(open);
    row->addWidget(use);
    row->addStretch(1);
    return row;
}

// The study's records, measure, parameter lists and search.
QLayout* StudyTab::buildForm() {
    m_measure->addItems({"pga", "sa"});
    m_floors->setPlaceholderText(tr("none: the ground record drives the slab"));
    m_folder->setPlaceholderText(tr("a folder of accelerograms (AT2, COSMOS, CSMIP V2, ...)"));
    auto* browse = new QPushButton(tr("Folder…"), this);
    connect(browse, &QPushButton::clicked, this, [this] {
        const QString d =
            QFileDialog::getExistingDirectory(this, tr("Records folder"), m_folder->text());
        if (!d.isEmpty()) m_folder->setText(d);
    });
    auto* folderRow = new QHBoxLayout;
    folderRow->addWidget(m_folder, 1);
    folderRow->addWidget(browse);
    auto* imRow = new QHBoxLayout;
    imRow->addWidget(m_measure);
    imRow->addWidget(new QLabel(tr("Sa period"), this));
    imRow->addWidget(m_saPeriod);
    // Two columns, the records and the parameters: five rows of fields rather than nine leave
    // the height to the results (the tab shares the window with the docks at 1280 x 800).
    auto* records = new QFormLayout;
    records->addRow(tr("Records folder"), folderRow);
    records->addRow(tr("Include files"), m_include);
    records->addRow(tr("Exclude files"), m_exclude);
    records->addRow(tr("Intensity measure"), imRow);
    auto* searchRow = new QHBoxLayout;
    searchRow->addWidget(m_maxG);
    searchRow->addWidget(new QLabel(tr("scan step"), this));
    searchRow->addWidget(m_step);
    auto* parameters = new QFormLayout;
    m_mu->setObjectName(QStringLiteral("mu")); // tests find the fields by name
    m_tstar->setObjectName(QStringLiteral("tstar"));
    parameters->addRow(tr("μ (LIST)"), m_mu);
    parameters->addRow(tr("t* s (LIST)"), m_tstar);
    parameters->addRow(tr("Floor periods s (LIST)"), m_floors);
    parameters->addRow(tr("Search up to"), searchRow);
    auto* form = new QHBoxLayout;
    form->addLayout(records, 3);
    form->addLayout(parameters, 2);
    return form;
}

// Run, cancel, progress and export.
QLayout* StudyTab::buildRunBar() {
    connect(m_run, &QPushButton::clicked, this, &StudyTab::run);
    connect(m_cancel, &QPushButton::clicked, this, &StudyTab::cancel);
    connect(m_export, &QPushButton::clicked, this, [this] {
        const QString f = QFileDialog::getSaveFileName(this, tr("Export study rows"),
                                                       inOpenProjectFolder("study.jsonl"),
                                                       tr("Study rows (*.jsonl)"));
        if (f.isEmpty() || !exportRows(f)) return;
        QString frag = f;
        frag.replace(QRegularExpression("\\.jsonl$"), "");
        exportFragility(frag + "-fragility.json");
    });
    m_cancel->setEnabled(false);
    m_export->setEnabled(false);
    m_status->setWordWrap(true);
    m_stale->setObjectName(QStringLiteral("studyStale")); // tests find it by name
    m_stale->setStyleSheet(StaleFrame::staleStyle());
    m_stale->setContentsMargins(8, 3, 8, 3);
    m_stale->hide();
    auto* bar = new QHBoxLayout;
    bar->addWidget(m_run);
    bar->addWidget(m_cancel);
    bar->addWidget(m_progress, 1);
    bar->addWidget(m_export);
    return bar;
}

// The fragility curves and the risk on the site's hazard curve as tabs, above the set and case
// tables.
QWidget* StudyTab::buildResults() {
    m_chart->setRenderHint(QPainter::Antialiasing);
    m_chart->setMinimumHeight(280);
    auto* views = new QTabWidget(this);
    views->addTab(m_chart, tr("Fragility"));
    views->addTab(m_risk, tr("Risk"));
    auto* split = new QSplitter(Qt::Vertical, this);
    split->addWidget(views);
    split->addWidget(m_sets);
    split->addWidget(m_table);
    split->setChildrenCollapsible(false);
    return split;
}

// Any field edited marks the results shown stale.
void StudyTab::connectFields() {
    for (QLineEdit* e : {m_folder, m_include, m_exclude, m_mu, m_tstar, m_floors})
        connect(e, &QLineEdit::textChanged, this, &StudyTab::updateStaleness);
    for (QDoubleSpinBox* b : {m_saPeriod, m_maxG, m_step})
        connect(b, &QDoubleSpinBox::valueChanged, this, &StudyTab::updateStaleness);
    connect(m_measure, &QComboBox::currentTextChanged, this, &StudyTab::updateStaleness);
}

StudyTab::~StudyTab() = default; // m_job cancels and waits

void StudyTab::setRecordsFolder(const QString& folder, const QString& include,
                                const QString& exclude) {
    m_folder->setText(folder);
    m_include->setText(include);
    m_exclude->setText(exclude);
}

void StudyTab::setLists(const QString& mu, const QString& tstar, const QString& floorPeriods) {
    m_mu->setText(mu);
    m_tstar->setText(tstar);
    m_floors->setText(floorPeriods);
}

void StudyTab::setSearch(double maxG, double scanStepG) {
    m_maxG->setValue(maxG);
    m_step->setValue(scanStepG);
}

QString StudyTab::message() const {
    return m_status->text();
}

bool StudyTab::exportRows(const QString& path) {
    return save(path, m_rows);
}

bool StudyTab::exportFragility(const QString& path) {
    // As kinstab-cli fragility writes it (its defaults are the fit's: core/study/Fragility.h).
    return save(path, jsonText(fragilityJson(m_fragility, {}), 2) + "\n");
}

bool StudyTab::save(const QString& path, const std::string& text) {
    try {
        writeFileAtomically(path.toStdString(), text);
        return true;
    } catch (const WriteError& e) {
        m_status->setText(tr("Cannot export: %1").arg(e.what()));
        return false;
    }
}

} // namespace kinstab::ui
