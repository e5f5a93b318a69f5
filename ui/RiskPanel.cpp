// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/RiskPanel.h"

#include "core/assessment/RiskCheck.h"
#include "core/base/InputLimits.h"
#include "core/base/TextInput.h"
#include "core/risk/HazardFile.h"
#include "core/study/StudySpec.h"
#include "ui/FieldError.h"
#include "ui/ProjectFolder.h"
#include "ui/RiskCharts.h"
#include "ui/RiskNumbersText.h"

#include <QChart>
#include <QChartView>
#include <QComboBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QTextDocument>
#include <QVBoxLayout>

namespace kinstab::ui {

RiskOutcome runRiskJob(const ProjectHazard& hazard, const std::vector<StudyRow>& rows,
                       std::optional<double> imG, SweepControl* control) {
    RiskOutcome o;
    const std::string where = "hazard curve " + quotedToken(hazard.file) + ": ";
    // The study's measure picks the USGS response and refuses a curve of another measure.
    const std::optional<HazardMeasure> measure = measureFromStudy(rows.front().measure);
    if (!measure) {
        o.error = where + "the study's intensity measure " + quotedToken(rows.front().measure) +
                  " is no measure a hazard curve is given in";
        return o;
    }
    std::optional<HazardSite> site;
    if (hazard.site) site = HazardSite{hazard.site->first, hazard.site->second};
    try {
        const HazardFormat format =
            hazardFormatFromName(hazard.format).value_or(HazardFormat::Auto);
        o.curve = readHazardFile(hazard.file, {format, site, measure});
        o.settings = riskSettingsOf(hazard);
        o.settings.imG = imG;
        o.sets = studySetRisks(o.curve, rows, o.settings, BootstrapSettings{}, control);
        o.cancelled = control->isCancelled();
    } catch (const HazardError& e) {
        o.error = where + e.what();
    } catch (const StudyError& e) {
        o.error = e.what();
    }
    return o;
}

RiskPanel::RiskPanel(QWidget* parent)
    : QWidget(parent), m_file(new QLineEdit(this)), m_imOfInterest(new QLineEdit(this)),
      m_imError(new QLabel(this)), m_set(new QComboBox(this)), m_status(new QLabel(this)),
      m_numbers(new QLabel(this)), m_hazardChart(new QChartView(new QChart, this)),
      m_fragilityChart(new QChartView(new QChart, this)),
      m_integrandChart(new QChartView(new QChart, this)), m_job(this) {
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(buildInputs());
    layout->addWidget(m_status);
    layout->addLayout(buildCharts(), 1);
    connect(&m_job, &BackgroundJob::failed, this, [this](const QString& e) {
        m_status->setText(tr("Cannot compute the risk: %1").arg(e));
        emit finished();
    });
    clear();
}

RiskPanel::~RiskPanel() = default; // m_job cancels and waits

// The hazard curve, the set shown and the intensity at which P(C) is asked.
QLayout* RiskPanel::buildInputs() {
    m_file->setReadOnly(true);
    m_file->setPlaceholderText(tr("the project's study.hazard, or pick a hazard curve"));
    auto* pick = new QPushButton(tr("Hazard curve…"), this);
    connect(pick, &QPushButton::clicked, this, [this] {
        const QString f = QFileDialog::getOpenFileName(
            this, tr("Hazard curve"),
            m_file->text().isEmpty() ? inOpenProjectFolder() : m_file->text(),
            tr("Hazard curves (*.csv *.json);;All files (*)"));
        if (!f.isEmpty()) setHazardFile(f);
    });
    m_imOfInterest->setPlaceholderText(tr("e.g. the MCE_R, g"));
    m_imOfInterest->setMaximumWidth(140);
    styleFieldError(m_imError);
    connect(m_imOfInterest, &QLineEdit::editingFinished, this, [this] {
        const QString text = m_imOfInterest->text().trimmed();
        const std::optional<double> x = parseDouble(text.toStdString());
        const bool ok = text.isEmpty() || (x && *x > 0.0 && *x <= limits::kMaxAmplitudeG);
        showFieldError(ok ? QString()
                          : tr("P(C) at = '%1': an intensity > 0 and at most %2 g, or empty")
                                .arg(text)
                                .arg(limits::kMaxAmplitudeG),
                       m_imErrorText, m_imError, m_imOfInterest);
        if (ok) setIntensityOfInterest(text.isEmpty() ? std::nullopt : x);
    });
    connect(m_set, &QComboBox::currentIndexChanged, this, [this] { showSet(); });
    auto* row = new QHBoxLayout;
    row->addWidget(new QLabel(tr("Hazard curve"), this));
    row->addWidget(m_file, 1);
    row->addWidget(pick);
    auto* choice = new QHBoxLayout;
    choice->addWidget(new QLabel(tr("Set"), this));
    choice->addWidget(m_set, 1);
    choice->addWidget(new QLabel(tr("P(C) at"), this));
    choice->addWidget(m_imOfInterest);
    auto* column = new QVBoxLayout;
    column->addLayout(row);
    column->addLayout(choice);
    column->addWidget(m_imError, 0, Qt::AlignRight);
    return column;
}

// Hazard and fragility above, the integrand and the numbers below: two columns fit the centre
// of a 1280 x 800 window (three charts and the numbers in a row need 1100 px), and the hazard
// curve and the integrand share their intensity axis's decades in one column.
QLayout* RiskPanel::buildCharts() {
    auto* grid = new QGridLayout;
    const QList<QChartView*> views = {m_hazardChart, m_fragilityChart, m_integrandChart};
    for (QChartView* v : views) {
        v->setRenderHint(QPainter::Antialiasing);
        v->setMinimumSize(300, 250);
        v->chart()->setMargins(QMargins(2, 2, 2, 2));
    }
    grid->addWidget(m_hazardChart, 0, 0);
    grid->addWidget(m_fragilityChart, 0, 1);
    grid->addWidget(m_integrandChart, 1, 0);
    m_numbers->setTextFormat(Qt::RichText);
    m_numbers->setWordWrap(true);
    m_numbers->setAlignment(Qt::AlignTop | Qt::AlignLeft);
    m_numbers->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_numbers->setMinimumWidth(300);
    grid->addWidget(m_numbers, 1, 1);
    grid->setColumnStretch(0, 1);
    grid->setColumnStretch(1, 1);
    m_status->setWordWrap(true);
    return grid;
}

void RiskPanel::setHazard(const std::optional<ProjectHazard>& h) {
    m_hazard = h;
    m_file->setText(h ? QString::fromStdString(h->file) : QString());
    recompute();
}

void RiskPanel::setHazardFile(const QString& path) {
    ProjectHazard h = m_hazard.value_or(ProjectHazard{});
    h.file = QFileInfo(path).absoluteFilePath().toStdString();
    h.format = "auto";
    h.site.reset(); // the picked file's first site
    setHazard(h);
}

void RiskPanel::setIntensityOfInterest(std::optional<double> imG) {
    m_imOfInterest->setText(imG ? QString::number(*imG, 'g', 6) : QString());
    m_imOfInterest->setProperty("value", imG ? QVariant(*imG) : QVariant());
    recompute();
}

void RiskPanel::setRows(const std::vector<StudyRow>& rows) {
    m_rows = rows;
    recompute();
}

void RiskPanel::clear() {
    m_job.discard();
    m_hazard.reset();
    m_rows.clear();
    m_file->clear();
    m_imOfInterest->clear();
    m_imOfInterest->setProperty("value", QVariant());
    recompute();
}

void RiskPanel::recompute() {
    m_job.discard(); // what it computes no longer matches the inputs
    m_outcome.reset();
    m_set->blockSignals(true);
    m_set->clear();
    m_set->blockSignals(false);
    showSet();
    if (!m_hazard) {
        m_status->setText(tr("No hazard curve: the project's study names none (study.hazard). "
                             "Pick one (OpenQuake hazard_curve CSV, USGS JSON or a CSV "
                             "im_g,annual_rate) in the study's intensity measure."));
        return;
    }
    if (m_rows.empty()) {
        m_status->setText(tr("The risk is computed from the study's results: run the study or "
                             "open a project whose study has results."));
        return;
    }
    const ProjectHazard hazard = *m_hazard;
    const std::vector<StudyRow> rows = m_rows;
    const QVariant v = m_imOfInterest->property("value");
    const std::optional<double> imG = v.isValid() ? std::optional(v.toDouble()) : std::nullopt;
    m_status->setText(tr("Integrating each set's fragility against %1…")
                          .arg(QFileInfo(m_file->text()).fileName()));
    m_job.start<RiskOutcome>(
        [hazard, rows, imG](JobContext& job) {
            job.control.onProgress = [&job](std::size_t done, std::size_t total) {
                job.done = done;
                job.total = total;
            };
            return runRiskJob(hazard, rows, imG, &job.control);
        },
        [this](RiskOutcome o) { showOutcome(std::move(o)); });
}

void RiskPanel::showOutcome(RiskOutcome o) {
    if (!o.error.empty() || o.cancelled) {
        m_status->setText(o.cancelled ? tr("Cancelled.") : QString::fromStdString(o.error));
        emit finished();
        return;
    }
    m_outcome = std::move(o);
    m_status->setText(tr("%1: %2 points from %3 g to %4 g (%5).")
                          .arg(QString::fromStdString(m_outcome->curve.source))
                          .arg(m_outcome->curve.points.size())
                          .arg(m_outcome->curve.points.front().imG)
                          .arg(m_outcome->curve.points.back().imG)
                          .arg(QString::fromStdString(m_outcome->curve.format)));
    m_set->blockSignals(true);
    for (const SetRisk& s : m_outcome->sets)
        m_set->addItem(riskSetName(s));
    m_set->blockSignals(false);
    showSet();
    emit finished();
}

void RiskPanel::selectSet(int index) {
    m_set->setCurrentIndex(index);
}

int RiskPanel::selectedSet() const {
    return m_set->currentIndex();
}

void RiskPanel::showSet() {
    const int i = m_set->currentIndex();
    if (!m_outcome || i < 0 || i >= static_cast<int>(m_outcome->sets.size())) {
        clearRiskChart(m_hazardChart->chart(), tr("Hazard curve"));
        clearRiskChart(m_fragilityChart->chart(), tr("Fragility of the set"));
        clearRiskChart(m_integrandChart->chart(), tr("Where λ_C comes from"));
        m_numbers->clear();
        return;
    }
    const RiskOutcome& o = *m_outcome;
    const SetRisk& set = o.sets[static_cast<std::size_t>(i)];
    fillHazardChart(m_hazardChart->chart(), o.curve, o.settings.targetRate);
    fillRiskFragilityChart(m_fragilityChart->chart(), o.curve, &set);
    fillIntegrandChart(m_integrandChart->chart(), o.curve, &set);
    m_numbers->setText(riskNumbersHtml(o.curve, o.settings, set));
}

QString RiskPanel::numbersText() const {
    QTextDocument d;
    d.setHtml(m_numbers->text());
    return d.toPlainText();
}

QString RiskPanel::message() const {
    return m_status->text();
}

} // namespace kinstab::ui
