// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/NumericsView.h"

#include <QCheckBox>
#include <QFontDatabase>
#include <QGraphicsLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPlainTextEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QSplitter>
#include <QVBoxLayout>
#include <QtCharts/QChart>
#include <QtCharts/QChartView>
#include <QtCharts/QLegendMarker>
#include <QtCharts/QLineSeries>
#include <QtCharts/QLogValueAxis>
#include <algorithm>
#include <cmath>
#include <map>

namespace kinstab::ui {

namespace {
// Errors of exactly zero (bit-identical to the reference) still need a place on a log axis.
constexpr double kErrorFloor = 1e-17;

QChart* workPrecisionChart() {
    auto* chart = new QChart;
    chart->setTitle(
        NumericsView::tr("Work-precision: error against run time (log-log), a line per case"));
    chart->setAnimationOptions(QChart::NoAnimation);
    // The legend (three solvers) beside the plot and no frame around the chart: at 1280 × 800
    // the tab is about 400 px tall, and every pixel of chrome comes off the plot.
    chart->legend()->setAlignment(Qt::AlignRight);
    chart->layout()->setContentsMargins(0, 0, 0, 0);
    chart->setBackgroundRoundness(0);
    return chart;
}

// The study's finite rows as (error, time) points, one curve per "case / solver", and the
// ranges both axes must hold (1 to 1 when there is no point).
struct PrecisionCurves {
    std::map<std::string, QList<QPointF>> curves;
    double lo = 1.0, hi = 1.0, tlo = 1.0, thi = 1.0;
};

PrecisionCurves precisionCurves(const WorkPrecisionStudy& study) {
    PrecisionCurves c;
    bool first = true;
    for (const WorkPrecisionRow& row : study.rows) {
        if (!std::isfinite(row.error) || !(row.timing.minSeconds > 0.0)) continue;
        const double e = std::max(row.error, kErrorFloor);
        const double t = row.timing.minSeconds;
        c.curves[row.caseId + " / " + row.solver].append({e, t});
        c.lo = first ? e : std::min(c.lo, e);
        c.hi = first ? e : std::max(c.hi, e);
        c.tlo = first ? t : std::min(c.tlo, t);
        c.thi = first ? t : std::max(c.thi, t);
        first = false;
    }
    return c;
}

QLogValueAxis* logAxis(const QString& title, double lo, double hi) {
    auto* a = new QLogValueAxis;
    a->setTitleText(title);
    a->setLabelFormat("%.0e");
    a->setRange(lo / 3.0, hi * 3.0);
    return a;
}

// One line per case and solver, coloured by solver, with one legend entry per solver: a
// legend entry per line (15 and more) took all but 30 px of the chart at 1280 × 800. The
// table below names every case. Returns the number of lines.
int addPrecisionCurves(QChart* chart, const PrecisionCurves& c, QAbstractAxis* x,
                       QAbstractAxis* y) {
    const QColor palette[] = {QColor(0x1f, 0x77, 0xb4), QColor(0xd6, 0x27, 0x28),
                              QColor(0x2c, 0xa0, 0x2c), QColor(0x94, 0x67, 0xbd),
                              QColor(0xff, 0x7f, 0x0e)};
    std::map<std::string, QColor> solverColour;
    int count = 0;
    for (const auto& [name, points] : c.curves) {
        const std::string solver = name.substr(name.rfind(" / ") + 3);
        const bool firstOfSolver = !solverColour.count(solver);
        if (firstOfSolver) solverColour[solver] = palette[solverColour.size() % std::size(palette)];
        auto* series = new QLineSeries;
        series->setName(QString::fromStdString(solver));
        series->setColor(solverColour[solver]);
        series->setPointsVisible(true);
        series->replace(points);
        chart->addSeries(series);
        series->attachAxis(x);
        series->attachAxis(y);
        if (!firstOfSolver)
            for (QLegendMarker* m : chart->legend()->markers(series))
                m->setVisible(false);
        ++count;
    }
    return count;
}

} // namespace

QHBoxLayout* NumericsView::buildBar() {
    m_run = new QPushButton(tr("Run study"), this);
    m_run->setToolTip(
        tr("Times every solver and setting on the fixed case set (paper grid at 1 Hz, "
           "grazing, chattering, high frequency, long duration) and measures its "
           "error against a converged reference."));
    m_cancel = new QPushButton(tr("Cancel"), this);
    m_cancel->setEnabled(false);
    m_regularized = new QCheckBox(tr("include regularized (tanh) friction — slow"), this);
    m_regularized->setToolTip(tr("Smoothed friction never sticks: it creeps and is stiff. "
                                 "Shown to explain why kinstab does not use it."));
    m_progress = new QProgressBar(this);
    m_progress->setFormat(tr("%v of %m settings"));
    auto* bar = new QHBoxLayout;
    bar->addWidget(m_run);
    bar->addWidget(m_cancel);
    bar->addWidget(m_regularized);
    bar->addWidget(m_progress, 1);
    return bar;
}

QSplitter* NumericsView::buildChartAndTable() {
    m_chart = new QChartView(workPrecisionChart(), this);
    m_chart->setRenderHint(QPainter::Antialiasing);
    m_table = new QPlainTextEdit(this);
    m_table->setReadOnly(true);
    m_table->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    m_table->setPlaceholderText(
        tr("Run the study to see the table (also: kinstab-cli precision)."));
    auto* split = new QSplitter(Qt::Vertical, this);
    split->addWidget(m_chart);
    split->addWidget(m_table);
    split->setStretchFactor(0, 3);
    // A readable plot (title, legend, log axes) and a few table lines whatever the splitter
    // was given: after a run the table's text pushed the chart down to 30 px at 1280 × 800.
    m_chart->setMinimumHeight(240);
    m_table->setMinimumHeight(4 * m_table->fontMetrics().lineSpacing() + 12);
    split->setChildrenCollapsible(false);
    split->setSizes({300, 100}); // in proportion: a quarter for the table
    return split;
}

NumericsView::NumericsView(QWidget* parent) : QWidget(parent), m_job(this) {
    QHBoxLayout* bar = buildBar();
    QSplitter* split = buildChartAndTable();
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(bar);
    layout->addWidget(split, 1);

    connect(m_run, &QPushButton::clicked, this, &NumericsView::startStudy);
    connect(m_cancel, &QPushButton::clicked, this, &NumericsView::cancelStudy);
    connect(&m_job, &BackgroundJob::progress, this, &NumericsView::onProgress);
    connect(&m_job, &BackgroundJob::ended, this, &NumericsView::onEnded);
}

NumericsView::~NumericsView() = default; // m_job cancels and waits

bool NumericsView::isRunning() const {
    return m_job.isRunning();
}

void NumericsView::startStudy() {
    if (isRunning()) return;
    WorkPrecisionOptions options;
    options.includeRegularized = m_regularized->isChecked();
    m_job.start<WorkPrecisionStudy>(
        [options](JobContext& job) mutable {
            options.onProgress = [&job](std::size_t done, std::size_t total) {
                job.total = total;
                job.done = done;
            };
            options.cancelled = [&job] { return job.isCancelled(); };
            return runWorkPrecisionStudy(options);
        },
        [this](WorkPrecisionStudy study) {
            if (!study.cancelled) showStudy(study);
        });
    m_run->setEnabled(false);
    m_cancel->setEnabled(true);
}

void NumericsView::cancelStudy() {
    m_job.cancel();
}

void NumericsView::onProgress(qint64 done, qint64 total) {
    m_progress->setRange(0, static_cast<int>(std::max<qint64>(total, 1)));
    m_progress->setValue(static_cast<int>(done));
}

void NumericsView::onEnded() {
    m_run->setEnabled(true);
    m_cancel->setEnabled(false);
}

int NumericsView::curveCount() const {
    return m_curves;
}

void NumericsView::showStudy(const WorkPrecisionStudy& study) {
    QChart* chart = m_chart->chart();
    chart->removeAllSeries();
    for (QAbstractAxis* axis : chart->axes())
        chart->removeAxis(axis);
    const PrecisionCurves c = precisionCurves(study);
    auto* x =
        logAxis(tr("error (relative τc, or residual δ / limit; 1 = wrong outcome)"), c.lo, c.hi);
    auto* y = logAxis(tr("run time, s (minimum of repeats)"), c.tlo, c.thi);
    chart->addAxis(x, Qt::AlignBottom);
    chart->addAxis(y, Qt::AlignLeft);
    m_curves = addPrecisionCurves(chart, c, x, y);
    m_table->setPlainText(QString::fromStdString(workPrecisionText(study)));
    emit studyShown();
}

} // namespace kinstab::ui
