// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/FloorsView.h"

#include "core/assessment/RunAssessment.h"
#include "core/io/FloorsJson.h"
#include "core/records/RecordReader.h"
#include "core/records/RecordText.h"
#include "ui/DockedChart.h"
#include "ui/FloorCharts.h"
#include "ui/ProjectFolder.h"
#include "ui/RecordPreview.h"

#include <QChartView>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFile>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>
#include <QSplitter>
#include <QVBoxLayout>

namespace kinstab::ui {

struct FloorsView::Outcome {
    FloorAnalysis analysis;
    Assessment checks; // the floor checks at the slab's level (core/assessment)
    Accelerogram ground;
    Building building;
    Slab1DCase slab;
    double searchLimit = 0;
};

namespace {

QChartView* chartView(QWidget* parent) {
    auto* chart = new QChart;
    chart->setAnimationOptions(QChart::NoAnimation);
    chart->setMargins(QMargins(4, 4, 4, 4));
    auto* v = new QChartView(parent);
    // Title and legend wrap onto more lines instead of eliding ("ASCE …" at 1280 × 800).
    installDockedChart(v, chart, QString());
    v->setMinimumSize(320, 260);
    return v;
}

// ":/records/..." (shipped) or a file; throws RecordError.
Accelerogram readGround(const QString& path) {
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        throw RecordError(path.toStdString(), 0, "cannot open the file");
    return parseRecord(RecordText(f.readAll().toStdString(), path.toStdString()));
}

} // namespace

FloorsView::FloorsView(std::function<Project()> source, QWidget* parent)
    : QWidget(parent), m_source(std::move(source)), m_record(new QLineEdit(this)),
      m_stiffness(new QComboBox(this)), m_damping(new QDoubleSpinBox(this)),
      m_slabLevel(new QSpinBox(this)), m_run(new QPushButton(tr("Run"), this)),
      m_cancel(new QPushButton(tr("Cancel"), this)), m_pick(new QSpinBox(this)),
      m_status(new QLabel(this)), m_verdicts(new QLabel(this)), m_profile(chartView(this)),
      m_critical(chartView(this)), m_level(chartView(this)) {
    setUpFields();
    QLayout* bar = buildRecordBar();
    auto* top = new QSplitter(Qt::Horizontal, this);
    top->addWidget(m_profile);
    top->addWidget(m_critical);
    auto* pickBar = new QHBoxLayout;
    pickBar->addWidget(new QLabel(tr("Show"), this));
    pickBar->addWidget(m_pick);
    pickBar->addWidget(m_status, 1);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(bar);
    layout->addWidget(top, 3);
    layout->addLayout(pickBar);
    layout->addWidget(m_level, 2);
    layout->addWidget(m_verdicts);

    connect(m_run, &QPushButton::clicked, this, &FloorsView::run);
    connect(m_cancel, &QPushButton::clicked, this, &FloorsView::cancel);
    connect(m_pick, &QSpinBox::valueChanged, this, &FloorsView::pickLevel);
}

// The record and the building's options, as a first start shows them.
void FloorsView::setUpFields() {
    m_record->setText(QStringLiteral(":/records/RSN77_SFERN_PUL164.AT2"));
    m_record->setToolTip(tr("The ground record (as recorded; the building filters it)."));
    m_stiffness->addItems({QStringLiteral("uniform"), QStringLiteral("weight")});
    m_stiffness->setToolTip(tr("Storey stiffness: equal, or proportional to the weight carried"));
    m_damping->setRange(0.0, 0.5);
    m_damping->setDecimals(3);
    m_damping->setSingleStep(0.01);
    m_damping->setValue(0.05);
    m_slabLevel->setRange(0, 200);
    m_slabLevel->setSpecialValueText(tr("roof"));
    m_cancel->setEnabled(false);
    m_pick->setRange(1, 1);
    m_pick->setPrefix(tr("level "));
    m_pick->setEnabled(false);
    m_status->setWordWrap(true);
    m_verdicts->setWordWrap(true);
    m_verdicts->setTextFormat(Qt::PlainText);
}

// Ground record, stiffness, damping, the slab's level, Run and Cancel in one row.
QLayout* FloorsView::buildRecordBar() {
    auto* browse = new QPushButton(tr("Record…"), this);
    auto* bar = new QHBoxLayout;
    bar->addWidget(new QLabel(tr("Ground record:"), this));
    bar->addWidget(m_record, 2);
    bar->addWidget(browse);
    bar->addWidget(new QLabel(tr("stiffness"), this));
    bar->addWidget(m_stiffness);
    bar->addWidget(new QLabel(tr("damping ζ"), this));
    bar->addWidget(m_damping);
    bar->addWidget(new QLabel(tr("slab on"), this));
    bar->addWidget(m_slabLevel);
    bar->addWidget(m_run);
    bar->addWidget(m_cancel);
    connect(browse, &QPushButton::clicked, this, [this] {
        const QString f = QFileDialog::getOpenFileName(
            this, tr("Ground record"), inOpenProjectFolder(), RecordPreview::fileDialogFilter());
        if (!f.isEmpty()) m_record->setText(f);
    });
    return bar;
}

FloorsView::~FloorsView() = default; // m_job cancels and waits

void FloorsView::setRecordPath(const QString& path) {
    m_record->setText(path);
}

bool FloorsView::isRunning() const {
    return m_job.isRunning();
}

QString FloorsView::message() const {
    return m_status->text();
}

void FloorsView::showEvent(QShowEvent* e) {
    QWidget::showEvent(e);
    applyProject(m_source());
    // Nothing run yet: say what the empty charts will hold.
    if (m_status->text().isEmpty())
        m_status->setText(tr("Run computes the building's modes, the floor motion of every level "
                             "and the critical ground PGA of the slab's level; they show here."));
}

// The project's record and floors settings fill the fields once each time they change, so a
// user's edits here survive switching tabs.
void FloorsView::applyProject(const Project& p) {
    const std::string record = p.record ? p.record->file : std::string();
    if (record != m_appliedRecord && !record.empty())
        m_record->setText(QString::fromStdString(record));
    m_appliedRecord = record;
    const std::string floors = p.floors ? floorSettingsToJson(*p.floors).dump() : std::string();
    if (floors != m_appliedFloors && p.floors) {
        m_stiffness->setCurrentText(QString::fromStdString(stiffnessName(p.floors->stiffness)));
        m_damping->setValue(p.floors->damping);
        m_slabLevel->setValue(p.floors->slabLevel.value_or(0));
    }
    m_appliedFloors = floors;
}

void FloorsView::run() {
    if (isRunning()) return;
    const Project p = m_source();
    FloorAnalysisInput in;
    try {
        in = floorAnalysisInput(p, readGround(m_record->text()));
    } catch (const RecordError& e) {
        m_status->setText(tr("Cannot read the record: %1").arg(e.what()));
        return;
    }
    in.settings.stiffness = *stiffnessFromName(m_stiffness->currentText().toStdString());
    in.settings.damping = m_damping->value();
    in.settings.slabLevel =
        m_slabLevel->value() > 0 ? std::optional<int>(m_slabLevel->value()) : std::nullopt;
    if (const std::string e = validateFloorAnalysis(in); !e.empty()) {
        m_status->setText(tr("Cannot run: %1").arg(QString::fromStdString(e)));
        return;
    }
    Project asRun = p;
    asRun.floors = in.settings;
    m_job.start<std::shared_ptr<Outcome>>(
        [in, asRun](JobContext& job) -> std::shared_ptr<Outcome> {
            auto o = std::make_shared<Outcome>();
            try {
                o->analysis = analyseFloors(in, &job.control);
            } catch (const std::exception&) {
                return nullptr; // validated above; a throw here is a bug, shown as a failed run
            }
            AssessmentParts parts;
            parts.floors = floorCheckParts(o->analysis, in.building.stories);
            parts.recordName = in.ground.name;
            o->checks = composeAssessment(asRun, parts);
            o->ground = in.ground;
            o->building = in.building;
            o->slab = in.slab;
            o->searchLimit = in.search.to;
            return o;
        },
        [this](std::shared_ptr<Outcome> o) { onFinished(std::move(o)); });
    m_status->setText(tr("Running: modes, floor motions, critical PGA of every level…"));
    m_run->setEnabled(false);
    m_cancel->setEnabled(true);
}

void FloorsView::cancel() {
    m_job.cancel();
}

void FloorsView::onFinished(std::shared_ptr<Outcome> o) {
    m_run->setEnabled(true);
    m_cancel->setEnabled(false);
    if (!o) {
        m_status->setText(tr("The analysis failed."));
        return;
    }
    if (o->analysis.cancelled) {
        m_status->setText(tr("Cancelled."));
        return;
    }
    m_shown = o;
    const Building& b = o->building;
    drawHeightCharts();
    m_pick->setEnabled(true);
    m_pick->setRange(1, b.stories);
    if (m_pick->value() == o->analysis.slabLevel)
        pickLevel(o->analysis.slabLevel);
    else
        m_pick->setValue(o->analysis.slabLevel); // draws through valueChanged
    showVerdicts();
    emit analysisShown();
}

void FloorsView::setUnitSystem(UnitSystem s) {
    if (s == m_units) return;
    m_units = s;
    if (m_shown) drawHeightCharts();
}

// Heights are kept in the building's unit (ft or m) and shown in the unit system's.
void FloorsView::drawHeightCharts() {
    const Building& b = m_shown->building;
    const double k = (b.unit == LengthUnit::Feet ? kMetresPerFoot : 1.0) /
                     metresPerUnit(m_units, LengthScale::Structure);
    std::vector<double> heights = levelHeights(b);
    for (double& h : heights)
        h *= k;
    const QString unit = lengthSymbol(m_units, LengthScale::Structure);
    fillProfileChart(m_profile->chart(), m_shown->analysis, heights, unit);
    fillCriticalChart(m_critical->chart(), m_shown->analysis, heights, unit);
}

void FloorsView::pickLevel(int level) {
    if (!m_shown || level < 1 || level > static_cast<int>(m_shown->analysis.motions.size())) return;
    const FloorAnalysis& a = m_shown->analysis;
    const QString run = fillLevelChart(m_level->chart(), a, m_shown->ground, m_shown->slab, level);
    const auto i = static_cast<std::size_t>(level - 1);
    QString crit = tr("no collapse up to the search limit");
    if (i < a.critical.size() && a.critical[i].criticalPga)
        crit = tr("critical PGA %1 g").arg(*a.critical[i].criticalPga, 0, 'f', 3);
    m_status->setText(tr("Level %1: PFA %2 g (%3 × PGA), %4; as recorded %5.")
                          .arg(level)
                          .arg(a.pfa[i], 0, 'f', 3)
                          .arg(a.pfa[i] / a.pga, 0, 'f', 2)
                          .arg(crit, run));
}

void FloorsView::showVerdicts() {
    const FloorAnalysis& a = m_shown->analysis;
    QStringList lines;
    lines
        << tr("Slab on level %1. First period %2 s (%3); SDOF filter at the roof %4 g, model %5 g.")
               .arg(a.slabLevel)
               .arg(a.building.period, 0, 'f', 3)
               .arg(QString::fromStdString(a.building.periodSource))
               .arg(a.sdofRoofPeak, 0, 'f', 3)
               .arg(a.pfa.back(), 0, 'f', 3);
    for (const Check& c : m_shown->checks.checks) {
        QStringList parts;
        for (const Comparison& x : c.comparisons)
            parts << tr("%1: %2 %3 g against %4 %5 (margin %6)")
                         .arg(QString::fromStdString(x.intensity))
                         .arg(QString::fromStdString(x.demandName))
                         .arg(x.demand, 0, 'f', 3)
                         .arg(QString::fromStdString(x.capacityName))
                         .arg(x.capacity ? QString::number(*x.capacity, 'f', 3) + " g"
                                         : tr("none up to the limit"))
                         .arg(QString::fromStdString(marginText(x)));
        lines << QStringLiteral("%1 — %2. %3")
                     .arg(QString::fromStdString(c.id), QString::fromStdString(c.verdict),
                          parts.join(QStringLiteral("; ")));
    }
    if (a.demands.empty()) lines << tr("The project selects neither ASCE 7-22 nor EN 1998-1.");
    m_verdicts->setText(lines.join('\n'));
}

} // namespace kinstab::ui
