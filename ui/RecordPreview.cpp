// SPDX-License-Identifier: GPL-3.0-or-later
// RecordPreview (ui/RecordPreview.h): the record read, the floor filter and the envelope fit, the
// info line; the charts in RecordPreviewCharts.cpp.
#include "ui/RecordPreview.h"

#include "core/records/ShippedRecords.h"
#include "ui/NiceAxisTicks.h"
#include "ui/RecordMetricsText.h"

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QFile>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QVBoxLayout>
#include <QtCharts/QChart>
#include <QtCharts/QChartView>
#include <QtCharts/QValueAxis>

namespace kinstab::ui {

namespace {

QChartView* makeView(const QString& title, const QString& xTitle, const QString& yTitle) {
    auto* chart = new QChart;
    chart->setTitle(title);
    chart->setAnimationOptions(QChart::NoAnimation);
    chart->legend()->setAlignment(Qt::AlignTop);
    auto* x = new QValueAxis;
    x->setTitleText(xTitle);
    auto* y = new QValueAxis;
    y->setTitleText(yTitle);
    chart->addAxis(x, Qt::AlignBottom);
    chart->addAxis(y, Qt::AlignLeft);
    useNiceTicks(chart);
    auto* view = new QChartView(chart);
    view->setRenderHint(QPainter::Antialiasing);
    view->setMinimumHeight(250); // below this the axis labels are elided to "…"
    return view;
}

} // namespace

RecordPreview::RecordPreview(QWidget* parent) : QWidget(parent) {
    info_ = new QLabel(tr("No record loaded."));
    info_->setWordWrap(true);
    info_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    info_->setToolTip(recordMetricsToolTip());
    info_->setObjectName(QStringLiteral("recordInfo")); // tests find it by name
    filterOn_ = new QCheckBox(tr("Floor filter"));
    filterOn_->setChecked(true);
    filterOn_->setToolTip(
        tr("Absolute acceleration of a damped linear oscillator under the record (paper eq. 6)"));
    period_ = new QDoubleSpinBox;
    period_->setRange(0.02, 20.0);
    period_->setDecimals(3);
    period_->setValue(1.0);
    period_->setSuffix(tr(" s"));
    period_->setToolTip(tr("Fundamental period T of the building"));
    damping_ = new QDoubleSpinBox;
    damping_->setRange(0.0, 99.0);
    damping_->setDecimals(1);
    damping_->setValue(2.0);
    damping_->setSuffix(tr(" %"));
    damping_->setToolTip(tr("Damping, per cent of critical (the paper uses 2 %)"));
    auto* controls = new QHBoxLayout;
    controls->addWidget(filterOn_);
    auto* form = new QFormLayout;
    form->addRow(tr("Period T"), period_);
    controls->addLayout(form);
    auto* form2 = new QFormLayout;
    form2->addRow(tr("Damping"), damping_);
    controls->addLayout(form2);
    controls->addStretch();

    groundView_ = makeView(tr("Ground acceleration"), tr("t (s)"), tr("a (g)"));
    floorView_ = makeView(tr("|Floor acceleration| and fitted envelope (Fig. 27)"), tr("t (s)"),
                          tr("|a| (g)"));
    spectrumView_ = makeView(tr("Fourier amplitude spectra, normalized (Figs. 25-26)"),
                             tr("f (Hz)"), tr("|X| / max"));
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(info_);
    layout->addLayout(controls);
    layout->addWidget(groundView_, 1);
    layout->addWidget(floorView_, 1);
    layout->addWidget(spectrumView_, 1);

    const auto changed = [this] { rebuild(); };
    connect(filterOn_, &QCheckBox::toggled, this, changed);
    connect(period_, &QDoubleSpinBox::valueChanged, this, changed);
    connect(damping_, &QDoubleSpinBox::valueChanged, this, changed);
}

QChart* RecordPreview::groundChart() const {
    return groundView_->chart();
}
QChart* RecordPreview::floorChart() const {
    return floorView_->chart();
}
QChart* RecordPreview::spectrumChart() const {
    return spectrumView_->chart();
}

QString RecordPreview::defaultVerticalRecord() {
    return QString::fromUtf8(kRsn68UpSource);
}

QString RecordPreview::defaultVerticalNote() {
    return tr(kRsn68UpNote);
}

QString RecordPreview::fileDialogFilter() {
    return tr("Accelerograms (*.AT2 *.at2 *.V1 *.V2 *.V1c *.V2c *.acc *.txt *.csv *.dat);;"
              "All files (*)");
}

bool RecordPreview::loadFile(const QString& path, const RecordReadOptions& options) {
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) {
        error_ = tr("%1: cannot open the file").arg(path);
        info_->setText(error_);
        return false;
    }
    try {
        setRecord(parseRecord(RecordText(f.readAll().toStdString(), path.toStdString()), options));
        return true;
    } catch (const RecordError& e) {
        error_ = QString::fromStdString(e.what());
        info_->setText(tr("Cannot read the record: %1").arg(error_));
        return false;
    }
}

void RecordPreview::setRecord(const Accelerogram& ground) {
    validateAccelerogram(ground);
    ground_ = ground;
    error_.clear();
    rebuild();
}

std::optional<FloorFilterParams> RecordPreview::floorFilter() const {
    if (!filterOn_->isChecked()) return std::nullopt;
    return FloorFilterParams{period_->value(), damping_->value() / 100.0, std::nullopt};
}

void RecordPreview::setFloorFilter(std::optional<FloorFilterParams> filter) {
    const QSignalBlocker b1(filterOn_), b2(period_), b3(damping_);
    filterOn_->setChecked(filter.has_value() && !planarBase_);
    if (filter) {
        period_->setValue(filter->period);
        damping_->setValue(filter->damping * 100.0);
    }
    rebuild();
}

void RecordPreview::setPlanarBase(bool planar) {
    if (planar == planarBase_) return;
    planarBase_ = planar;
    const QSignalBlocker block(filterOn_);
    if (planar) filterOn_->setChecked(false);
    filterOn_->setEnabled(!planar);
    filterOn_->setToolTip(
        planar ? tr("Off for a planar project: the record is the slab's vertical base motion, "
                    "applied as recorded")
               : tr("Absolute acceleration of a damped linear oscillator under the record "
                    "(paper eq. 6)"));
    rebuild();
}

void RecordPreview::rebuild() {
    period_->setEnabled(filterOn_->isChecked());
    damping_->setEnabled(filterOn_->isChecked());
    if (!ground_) return;
    const std::optional<FloorFilterParams> filter = floorFilter();
    floor_.reset();
    if (filter && validateFloorFilter(*filter).empty())
        floor_ = kinstab::floorMotion(*ground_, *filter);
    fit_.reset();
    try {
        fit_ = fitEnvelope(floor_ ? *floor_ : *ground_);
    } catch (const std::invalid_argument&) {
    }
    metrics_ = recordMetrics(*ground_, period_->value()); // the spin box's range is Sa's
    plotGround();
    plotFloor();
    plotSpectra();
    showInfo();
    emit recordChanged();
}

void RecordPreview::showInfo() {
    const Accelerogram& a = *ground_;
    const SignedPeak p = a.peak();
    QString text =
        tr("<b>%1</b><br>%2 — %3 · %4 points at %5 s (%6 s) · peak %7 g at %8 s · file units %9")
            .arg(QString::fromStdString(a.name).toHtmlEscaped(),
                 QString::fromStdString(a.station).toHtmlEscaped(),
                 QString::fromStdString(a.component).toHtmlEscaped())
            .arg(a.size())
            .arg(a.dt)
            .arg(a.duration(), 0, 'f', 2)
            .arg(p.value, 0, 'f', 4)
            .arg(p.time, 0, 'f', 2)
            .arg(QString::fromStdString(accelUnitName(a.fileUnit)));
    if (metrics_) text += "<br>" + recordMetricsLine(*metrics_);
    if (floor_) text += tr("<br>Floor motion peak %1 g").arg(floor_->peak().value, 0, 'f', 4);
    if (fit_)
        text += tr(" · envelope fit α = %1 /s, β = %2 /s, peak %3 g at %4 s")
                    .arg(fit_->alpha, 0, 'f', 4)
                    .arg(fit_->beta, 0, 'f', 4)
                    .arg(fit_->peak(), 0, 'f', 3)
                    .arg(fit_->peakTime(), 0, 'f', 2);
    if (QString::fromStdString(a.sourceFile).endsWith("RSN68_SFERN_PEL-UP.AT2"))
        text += "<br><i>" + defaultVerticalNote() + "</i>";
    info_->setText(text);
}

} // namespace kinstab::ui
