// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/FrictionPanel.h"

#include "core/friction/TripletCsv.h"
#include "ui/NiceAxisTicks.h"
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
#include <QLegendMarker>
#include <QLineSeries>
#include <QPushButton>
#include <QScatterSeries>
#include <QSplitter>
#include <QTableWidget>
#include <QVBoxLayout>
#include <QValueAxis>

#include <algorithm>
#include <cmath>

namespace kinstab::ui {
namespace {

const char* kBuiltIn = ":/data/furgerson1980/table1_triplet_tests.csv";

// The shown units per unit system: the paper's tests are kept in kip, psi and in.
struct ShownUnits {
    double force, pressure, length, area; // shown per kip, psi, in, in²
    QString f, p, l, a;
};

ShownUnits shownUnits(UnitSystem s) {
    if (s == UnitSystem::US) return {1.0, 1.0, 1.0, 1.0, "kip", "psi", "in", "in²"};
    // 1 lbf = 4.4482216152605 N and 1 in = 25.4 mm exactly (NIST SP 811, appendix B).
    // psi = lbf/in²: 4.4482216152605e-3 kN over 0.0254² m² = 6.894757 kPa.
    const double kN = 4.4482216152605, kPa = kN * 1e-3 / (0.0254 * 0.0254);
    return {kN, kPa, 25.4, 6.4516, "kN", "kPa", "mm", "cm²"};
}

// The decay law's c has the unit 1 / (length · (force · length)^β): xi is δ weighted by the
// work W^β (Eq. 2). b is a pure number.
double shownDecayRate(double cPerInch, double beta, const ShownUnits& u) {
    return cPerInch / (u.length * std::pow(u.force * u.length, beta));
}

QStringList tableHeader(const ShownUnits& u) {
    return {QObject::tr("Configuration"),
            QObject::tr("CP %1").arg(u.p),
            QObject::tr("Tests"),
            QObject::tr("V1 %1").arg(u.f),
            QObject::tr("V∞ %1").arg(u.f),
            QObject::tr("c 1/%1·(%2·%1)^β").arg(u.l, u.f),
            QObject::tr("b"),
            QObject::tr("β"),
            QObject::tr("f_m %1²").arg(u.f),
            QObject::tr("Outlier (Grubbs 95 %)")};
}

QColor cpColor(int i) {
    static const QColor colors[] = {QColor(0x1f77b4), QColor(0xd62728), QColor(0x2ca02c),
                                    QColor(0x9467bd), QColor(0xff7f0e), QColor(0x8c564b),
                                    QColor(0x17becf)};
    return colors[i % 7];
}

QValueAxis* axis(const QString& title, double lo, double hi) {
    auto* a = new QValueAxis;
    a->setTitleText(title);
    a->setRange(lo, hi);
    useNiceTicks(a);
    return a;
}

// Attaches the series to fresh axes (the chart owns everything).
void resetChart(QChart* chart, const QList<QAbstractSeries*>& series, QValueAxis* x,
                QValueAxis* y) {
    chart->removeAllSeries();
    for (QAbstractAxis* a : chart->axes())
        chart->removeAxis(a), delete a;
    chart->addAxis(x, Qt::AlignBottom);
    chart->addAxis(y, Qt::AlignLeft);
    for (QAbstractSeries* s : series) {
        chart->addSeries(s);
        s->attachAxis(x);
        s->attachAxis(y);
        // Test points share their fit's colour; the legend lists the lines only.
        if (s->type() == QAbstractSeries::SeriesTypeScatter && s->property("hideInLegend").toBool())
            for (QLegendMarker* m : chart->legend()->markers(s))
                m->setVisible(false);
    }
}

QChartView* makeChartView(const QString& title) {
    auto* chart = new QChart;
    chart->setTitle(title);
    chart->setAnimationOptions(QChart::NoAnimation);
    chart->legend()->setAlignment(Qt::AlignRight);
    auto* view = new QChartView(chart);
    view->setRenderHint(QPainter::Antialiasing);
    // Two side by side fit the tab at 1280 × 800 (about 830 px): at 420 px each the tab
    // scrolled sideways and "Use this μ" was cut at the right.
    view->setMinimumSize(360, 340);
    return view;
}

} // namespace

FrictionPanel::FrictionPanel(QWidget* parent) : QWidget(parent) {
    buildUi();
    QString error;
    if (!loadCsv(kBuiltIn, &error)) status_->setText(error);
}

void FrictionPanel::buildUi() {
    auto* open = new QPushButton(tr("Open CSV…"));
    configuration_ = new QComboBox;
    slopeKind_ = new QComboBox;
    slopeKind_->addItems({tr("least squares with intercept"), tr("through the origin")});
    area_ = new QDoubleSpinBox;
    area_->setRange(0.0, 1e5);
    area_->setDecimals(2);
    area_->setSuffix(QStringLiteral(" in²"));
    area_->setSpecialValueText(tr("not set"));
    area_->setToolTip(tr("Bearing area A_b: tau_inf = V_inf / A_b (not given in Furgerson 1980)"));
    useMu_ = new QPushButton(tr("Use this μ"));
    useMu_->setObjectName("useMu");
    muLabel_ = new QLabel;
    status_ = new QLabel;
    status_->setWordWrap(true);

    auto* controls = new QHBoxLayout;
    controls->addWidget(open);
    controls->addWidget(new QLabel(tr("Configuration")));
    controls->addWidget(configuration_);
    controls->addWidget(new QLabel(tr("A_b")));
    controls->addWidget(area_);
    controls->addWidget(slopeKind_);
    controls->addStretch(1);
    // The fitted μ and its button on a line of their own: beside the controls above they made
    // the row wider than the tab at 1280 × 800 and the button was cut at the right.
    auto* muRow = new QHBoxLayout;
    muRow->addWidget(muLabel_, 1);
    muRow->addWidget(useMu_);

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

    auto* layout = new QVBoxLayout(this);
    layout->addLayout(controls);
    layout->addLayout(muRow);
    layout->addWidget(split, 1);
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

void FrictionPanel::fillCurveChart() {
    // Figs. 18-20: the composite test curve (points) and the fitted decay law (line) per CP.
    const ShownUnits u = shownUnits(units_);
    QList<QAbstractSeries*> series;
    double vMax = 1.0, dMax = 0.0;
    int k = 0;
    for (const GroupCalibration& g : calibration_.groups) {
        if (QString::fromStdString(g.configuration) != configuration_->currentText()) continue;
        const TripletCurve& c = g.composite;
        const Eigen::VectorXd dense =
            Eigen::VectorXd::LinSpaced(121, c.delta(0), c.delta(c.delta.size() - 1));
        const Eigen::VectorXd fitted = evaluateDecay(g.fit, c, dense);
        QList<QPointF> line, points;
        for (Eigen::Index i = 0; i < dense.size(); ++i)
            line.append({u.length * dense(i), u.force * fitted(i)});
        for (Eigen::Index i = 0; i < c.delta.size(); ++i)
            points.append({u.length * c.delta(i), u.force * c.shear(i)});
        auto* l = new QLineSeries;
        l->replace(line);
        l->setName(tr("CP %1 %2").arg(g.cpPsi * u.pressure, 0, 'f', 0).arg(u.p));
        l->setPen(QPen(cpColor(k), 2));
        auto* s = new QScatterSeries;
        s->replace(points);
        s->setName(tr("CP %1 test").arg(g.cpPsi * u.pressure, 0, 'f', 0));
        s->setProperty("hideInLegend", true);
        s->setColor(cpColor(k));
        s->setMarkerSize(7);
        series << s << l;
        vMax = std::max(vMax, u.force * c.shear.maxCoeff());
        dMax = std::max(dMax, u.length * c.delta.maxCoeff());
        ++k;
    }
    curves_->chart()->setTitle(tr("%1: V(δ) after fracture, composite tests and fitted law")
                                   .arg(configuration_->currentText()));
    resetChart(curves_->chart(), series,
               axis(tr("δ (%1)").arg(u.l), 0.0, dMax > 0 ? dMax : 0.4 * u.length),
               axis(tr("V (%1)").arg(u.f), 0.0, 1.05 * vMax));
}

void FrictionPanel::fillCoulombChart() {
    // Fig. 21: V_inf (or tau_inf with A_b) against CP, with the least-squares line for CP <= limit.
    const ShownUnits u = shownUnits(units_);
    const bool withArea = areaIn2_ > 0.0;
    // kips -> psi over A_b, then into the shown pressure (or force) unit.
    const double scale = withArea ? u.pressure * 1000.0 / bearingAreaIn2() : u.force;
    const bool intercept = slopeKind_->currentIndex() == 0;
    QList<QAbstractSeries*> series;
    double yMax = 1.0, cpMax = 100.0 * u.pressure;
    int k = 0;
    for (const ConfigurationCalibration& c : calibration_.configurations) {
        QList<QPointF> used, excluded, line;
        for (const CoulombPoint& p : c.points) {
            (p.cpPsi <= calibration_.options.maxCpPsi ? used : excluded)
                .append({u.pressure * p.cpPsi, scale * p.vInfKips});
            yMax = std::max(yMax, scale * p.vInfKips);
            cpMax = std::max(cpMax, u.pressure * p.cpPsi);
        }
        auto* s = new QScatterSeries;
        s->replace(used);
        s->setName(QString::fromStdString(c.configuration));
        s->setColor(cpColor(k));
        series << s;
        if (!excluded.isEmpty()) {
            auto* x = new QScatterSeries;
            x->replace(excluded);
            x->setName(tr("%1 (excluded)").arg(QString::fromStdString(c.configuration)));
            x->setMarkerShape(QScatterSeries::MarkerShapeRectangle);
            x->setColor(cpColor(k).lighter(160));
            series << x;
        }
        if (c.coulomb) {
            const double slope =
                intercept ? c.coulomb->slopeWithIntercept : c.coulomb->slopeThroughOrigin;
            const double v0 = intercept ? c.coulomb->interceptKips : 0.0;
            const double top = calibration_.options.maxCpPsi;
            line << QPointF(0.0, scale * v0)
                 << QPointF(u.pressure * top, scale * (v0 + slope * top));
            auto* l = new QLineSeries;
            l->replace(line);
            l->setName(tr("%1 fit").arg(QString::fromStdString(c.configuration)));
            l->setPen(QPen(cpColor(k), 2, Qt::DashLine));
            series << l;
        }
        ++k;
    }
    coulomb_->chart()->setTitle(withArea ? tr("τ∞ = V∞ / A_b against confining pressure")
                                         : tr("V∞ against confining pressure"));
    resetChart(coulomb_->chart(), series, axis(tr("CP (%1)").arg(u.p), 0.0, 1.05 * cpMax),
               axis(withArea ? tr("τ∞ (%1)").arg(u.p) : tr("V∞ (%1)").arg(u.f), 0.0, 1.1 * yMax));
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
