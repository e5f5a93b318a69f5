// SPDX-License-Identifier: GPL-3.0-or-later
// FrictionPanel (ui/FrictionPanel.h): the tab, the tests read, the calibration and its table; the
// charts in FrictionPanelCharts.cpp.
#include "ui/FrictionPanel.h"

#include "core/friction/TripletCsv.h"
#include "ui/FrictionChartParts.h"
#include "ui/ProjectFolder.h"

#include <QChart>
#include <QChartView>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFile>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QSplitter>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace kinstab::ui {

using namespace friction;

namespace {

const char* kBuiltIn = ":/data/furgerson1980/table1_triplet_tests.csv";

// The decay law's c has the unit 1 / (length · (force · length)^β): xi is δ weighted by the
// work W^β (Eq. 2). b is a pure number.
double shownDecayRate(double cPerInch, double beta, const ShownUnits& u) {
    return cPerInch / (u.length * std::pow(u.force * u.length, beta));
}

// f_m's unit goes in squared: in "%1²" QString::arg reads ² as a digit, placeholder %12.
QStringList tableHeader(const ShownUnits& u) {
    return {QObject::tr("Configuration"),
            QObject::tr("CP %1").arg(u.p),
            QObject::tr("Tests"),
            QObject::tr("V1 %1").arg(u.f),
            QObject::tr("V∞ %1").arg(u.f),
            QObject::tr("c 1/%1·(%2·%1)^β").arg(u.l, u.f),
            QObject::tr("b"),
            QObject::tr("β"),
            QObject::tr("f_m %1").arg(u.f + QStringLiteral("²")),
            QObject::tr("Outlier (Grubbs 95 %)")};
}

} // namespace

FrictionPanel::FrictionPanel(QWidget* parent) : QWidget(parent) {
    buildUi();
    QString error;
    if (!loadCsv(kBuiltIn, &error)) status_->setText(error);
}

void FrictionPanel::buildUi() {
    auto* open = new QPushButton(tr("Open CSV…"));
    QLayout* controls = buildControls(open);
    QLayout* muRow = buildMuRow();
    status_ = new QLabel;
    status_->setWordWrap(true);
    QWidget* results = buildResults();

    auto* layout = new QVBoxLayout(this);
    layout->addLayout(controls);
    layout->addLayout(muRow);
    layout->addWidget(results, 1);
    layout->addWidget(status_);

    connect(open, &QPushButton::clicked, this, &FrictionPanel::openFile);
    connect(configuration_, &QComboBox::currentTextChanged, this, &FrictionPanel::refresh);
    connect(slopeKind_, &QComboBox::currentIndexChanged, this, &FrictionPanel::refresh);
    connect(area_, &QDoubleSpinBox::valueChanged, this, [this](double shown) {
        areaIn2_ = shown * shownUnits(units_).area;
        recalibrate();
    });
    connect(useMu_, &QPushButton::clicked, this, [this] {
        if (const auto mu = currentMu()) emit useMu(*mu);
    });
}

// Open, the configuration, the bearing area and the slope's fit in one row.
QLayout* FrictionPanel::buildControls(QPushButton* open) {
    configuration_ = new QComboBox;
    slopeKind_ = new QComboBox;
    slopeKind_->addItems({tr("least squares with intercept"), tr("through the origin")});
    area_ = new QDoubleSpinBox;
    area_->setRange(0.0, 1e5);
    area_->setDecimals(2);
    area_->setSuffix(QStringLiteral(" in²"));
    area_->setSpecialValueText(tr("not set"));
    area_->setToolTip(tr("Bearing area A_b: tau_inf = V_inf / A_b (not given in Furgerson 1980)"));
    auto* controls = new QHBoxLayout;
    controls->addWidget(open);
    controls->addWidget(new QLabel(tr("Configuration")));
    controls->addWidget(configuration_);
    controls->addWidget(new QLabel(tr("A_b")));
    controls->addWidget(area_);
    controls->addWidget(slopeKind_);
    controls->addStretch(1);
    return controls;
}

// The fitted μ and its button on a line of their own: beside the controls above they made the
// row wider than the tab at 1280 × 800 and the button was cut at the right.
QLayout* FrictionPanel::buildMuRow() {
    useMu_ = new QPushButton(tr("Use this μ"));
    useMu_->setObjectName("useMu");
    muLabel_ = new QLabel;
    auto* muRow = new QHBoxLayout;
    muRow->addWidget(muLabel_, 1);
    muRow->addWidget(useMu_);
    return muRow;
}

// The two charts side by side above the table of fits.
QWidget* FrictionPanel::buildResults() {
    curves_ = makeChartView(tr("Shear force after fracture"));
    coulomb_ = makeChartView(tr("Asymptotic friction law"));
    table_ = new QTableWidget(0, 10);
    table_->setHorizontalHeaderLabels(tableHeader(shownUnits(units_)));
    table_->setObjectName("fits");
    table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table_->verticalHeader()->hide();
    table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    table_->horizontalHeader()->setStretchLastSection(true);

    auto* charts = new QSplitter(Qt::Horizontal);
    charts->addWidget(curves_);
    charts->addWidget(coulomb_);
    auto* split = new QSplitter(Qt::Vertical);
    split->addWidget(charts);
    split->addWidget(table_);
    split->setStretchFactor(0, 3);
    split->setStretchFactor(1, 2);
    split->setSizes({560, 300});
    // The header and four rows at least: the splitter squeezed the table to its header when
    // the tab was short; the scroll area around the tab scrolls instead.
    table_->setMinimumHeight(table_->horizontalHeader()->sizeHint().height() +
                             4 * table_->verticalHeader()->defaultSectionSize() +
                             2 * table_->frameWidth());
    split->setChildrenCollapsible(false);
    return split;
}

bool FrictionPanel::loadCsv(const QString& path, QString* error) {
    QFile file(path);
    QString message;
    if (!file.open(QIODevice::ReadOnly)) {
        message = tr("%1: cannot open the file").arg(path);
    } else {
        try {
            setRuns(parseTripletCsv(file.readAll().toStdString(), path.toStdString()), path);
            return true;
        } catch (const std::exception& e) {
            message = QString::fromStdString(e.what());
        }
    }
    status_->setText(message);
    if (error) *error = message;
    return false;
}

void FrictionPanel::setRuns(const std::vector<TripletCurve>& runs, const QString& sourceName) {
    runs_ = runs;
    source_ = sourceName;
    const QString keep = configuration_->currentText();
    QSignalBlocker block(configuration_);
    configuration_->clear();
    for (const TripletCurve& r : runs_)
        if (configuration_->findText(QString::fromStdString(r.configuration)) < 0)
            configuration_->addItem(QString::fromStdString(r.configuration));
    if (configuration_->findText(keep) >= 0) configuration_->setCurrentText(keep);
    recalibrate();
}

void FrictionPanel::setConfiguration(const QString& c) {
    configuration_->setCurrentText(c);
}
void FrictionPanel::setBearingArea(double in2) {
    areaIn2_ = in2;
    {
        QSignalBlocker block(area_);
        area_->setValue(in2 / shownUnits(units_).area);
    }
    recalibrate();
}

void FrictionPanel::setUnitSystem(UnitSystem s) {
    if (s == units_) return;
    units_ = s;
    const ShownUnits u = shownUnits(s);
    table_->setHorizontalHeaderLabels(tableHeader(u));
    {
        QSignalBlocker block(area_);
        area_->setSuffix(QStringLiteral(" ") + u.a);
        area_->setValue(areaIn2_ / u.area);
    }
    recalibrate();
}
void FrictionPanel::setWithIntercept(bool w) {
    slopeKind_->setCurrentIndex(w ? 0 : 1);
}
int FrictionPanel::tableRows() const {
    return table_->rowCount();
}

std::optional<double> FrictionPanel::currentMu() const {
    for (const ConfigurationCalibration& c : calibration_.configurations) {
        if (QString::fromStdString(c.configuration) != configuration_->currentText() || !c.coulomb)
            continue;
        return slopeKind_->currentIndex() == 0 ? c.coulomb->muWithIntercept
                                               : c.coulomb->muThroughOrigin;
    }
    return std::nullopt;
}

void FrictionPanel::recalibrate() {
    CalibrationOptions o;
    if (areaIn2_ > 0.0) o.bearingAreaIn2 = areaIn2_;
    try {
        calibration_ = calibrateFriction(runs_, o);
        status_->setText(
            tr("%1: %2 tests, %3 groups. Decay law fitted with α = 2, β = 0 or 1/3 (smaller f_m); "
               "μ∞ from CP ≤ %4 %5.")
                .arg(source_)
                .arg(runs_.size())
                .arg(calibration_.groups.size())
                .arg(o.maxCpPsi * shownUnits(units_).pressure, 0, 'f', 0)
                .arg(shownUnits(units_).p));
    } catch (const std::exception& e) {
        calibration_ = {};
        status_->setText(QString::fromStdString(e.what()));
    }
    refresh();
}

void FrictionPanel::refresh() {
    fillCurveChart();
    fillCoulombChart();
    fillTable();
    const auto mu = currentMu();
    useMu_->setEnabled(mu.has_value());
    muLabel_->setText(mu ? tr("μ∞ = %1").arg(*mu, 0, 'f', 3) : tr("μ∞: set the bearing area A_b"));
}

void FrictionPanel::fillTable() {
    const ShownUnits u = shownUnits(units_);
    table_->setRowCount(0);
    for (const GroupCalibration& g : calibration_.groups) {
        const int row = table_->rowCount();
        table_->insertRow(row);
        QString outlier = tr("not tested (%1 runs)").arg(g.runs.size());
        if (g.outlier)
            outlier =
                tr("%1: G = %2 vs %3")
                    .arg(g.outlier->rejected
                             ? tr("test %1 rejected")
                                   .arg(QString::fromStdString(g.runs[g.outlier->index].curve.test))
                             : tr("none"))
                    .arg(g.outlier->statistic, 0, 'f', 3)
                    .arg(g.outlier->critical, 0, 'f', 3);
        const QStringList cells = {QString::fromStdString(g.configuration),
                                   QString::number(g.cpPsi * u.pressure, 'f', 0),
                                   QString::fromStdString(g.composite.test),
                                   QString::number(g.fit.v1 * u.force, 'f', 2),
                                   QString::number(g.fit.vInf * u.force, 'f', 2),
                                   QString::number(shownDecayRate(g.fit.c, g.fit.beta, u), 'g', 3),
                                   QString::number(g.fit.b, 'f', 3),
                                   g.fit.beta == 0.0 ? "0" : "1/3",
                                   QString::number(g.fit.fm * u.force * u.force, 'f', 3),
                                   outlier};
        for (int col = 0; col < cells.size(); ++col)
            table_->setItem(row, col, new QTableWidgetItem(cells[col]));
    }
}

void FrictionPanel::openFile() {
    const QString path = QFileDialog::getOpenFileName(this, tr("Triplet shear tests"),
                                                      inOpenProjectFolder(), tr("CSV (*.csv)"));
    if (!path.isEmpty()) loadCsv(path);
}

} // namespace kinstab::ui
