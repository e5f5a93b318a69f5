// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/teaching/ParameterPanel.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QSlider>

#include <cmath>

namespace kinstab::ui {

namespace {
constexpr int kA = 0, kF = 1, kMu = 2, kD = 3;
}

ParameterPanel::ParameterPanel(QWidget* parent) : QWidget(parent) {
    auto* grid = new QGridLayout(this);
    grid->setContentsMargins(0, 0, 0, 0);
    buildChoices(grid);
    buildNumberRows(grid);
    buildPlanarRows(grid);
    grid->setColumnStretch(1, 1);
    setParams(TeachingParams{});
    connect(model_, &QComboBox::currentIndexChanged, this, &ParameterPanel::changed);
    connect(envelope_, &QComboBox::currentIndexChanged, this, &ParameterPanel::changed);
    connect(scale_, &QComboBox::currentIndexChanged, this, &ParameterPanel::changed);
    connect(limit_, &QDoubleSpinBox::valueChanged, this, &ParameterPanel::changed);
}

// Rows 0-2: the model, the envelope and the γc scaling.
void ParameterPanel::buildChoices(QGridLayout* grid) {
    envelope_ = new QComboBox(this);
    envelope_->addItem(tr("fast rising"), int(EnvelopePreset::Fast));
    envelope_->addItem(tr("moderately rising"), int(EnvelopePreset::Moderate));
    envelope_->addItem(tr("slowly rising"), int(EnvelopePreset::Slow));
    scale_ = new QComboBox(this);
    scale_->addItem(tr("γc = τ_max / τc"), int(TauScale::TauMax));
    scale_->addItem(tr("γc = τ_rise / τc"), int(TauScale::TauRise));
    scale_->addItem(tr("γc = τ_dur / τc"), int(TauScale::TauDur));
    scale_->addItem(tr("γc = 1 / τc"), int(TauScale::One));
    model_ = new QComboBox(this);
    model_->addItem(tr("one degree of freedom (ch. IV)"), int(TeachingModel::Slab1D));
    model_->addItem(tr("planar, two degrees (ch. VI)"), int(TeachingModel::Planar));
    grid->addWidget(new QLabel(tr("Model"), this), 0, 0);
    grid->addWidget(model_, 0, 1, 1, 2);
    grid->addWidget(new QLabel(tr("Envelope"), this), 1, 0);
    grid->addWidget(envelope_, 1, 1, 1, 2);
    grid->addWidget(new QLabel(tr("Scaling"), this), 2, 0);
    grid->addWidget(scale_, 2, 1, 1, 2);
    // The panel has a fixed width (TeachingView's side column): combo boxes as wide as their
    // longest entry made the grid wider than it, and the value column on the right was cut.
    for (QComboBox* c : {model_, envelope_, scale_}) {
        c->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
        c->setMinimumContentsLength(10);
    }
}

// Rows 3-7: A, f, μ and the wall width as slider and box, and the bearing length.
void ParameterPanel::buildNumberRows(QGridLayout* grid) {
    rows_[kA] = addRow(grid, kA, tr("A"), 0.0, 3.0, 0.005, 3, tr(" g"));
    rows_[kF] = addRow(grid, kF, tr("f"), 0.05, 5.0, 0.005, 3, tr(" Hz"));
    rows_[kMu] = addRow(grid, kMu, tr("μ"), 0.05, 1.5, 0.01, 2, QString());
    rows_[kD] = addRow(grid, kD, tr("wall d"), 50.0, 500.0, 0.5, 1, tr(" mm"));
    limit_ = new QDoubleSpinBox(this);
    limit_->setRange(0.1, 2.0);
    limit_->setSingleStep(0.05);
    limit_->setDecimals(2);
    limit_->setToolTip(tr("Bearing length / (d/2): the slab falls when |δ| exceeds it (paper: 1)"));
    grid->addWidget(new QLabel(tr("bearing"), this), 7, 0);
    grid->addWidget(limit_, 7, 1);
    grid->addWidget(new QLabel(tr("× d/2"), this), 7, 2);
}

// Rows 8-11: the planar model's own inputs and the t* line.
void ParameterPanel::buildPlanarRows(QGridLayout* grid) {
    fy_ = addSpin(grid, 8, tr("f_y"), 0.05, 20.0, 0.05, 3, tr(" Hz"),
                  tr("Planar: frequency along the walls"), &TeachingParams::fyHz);
    ayRatio_ = addSpin(grid, 9, tr("A_y/A_x"), 0.0, 2.0, 0.05, 2, QString(),
                       tr("Planar: amplitude along the walls over across (paper: 0.9)"),
                       &TeachingParams::ayRatio);
    theta_ = addSpin(
        grid, 10, tr("Θ"), 1.0, 200.0, 1.0, 1, QString(),
        tr("Planar: 2 wall length / wall width; collapse along the walls at |δy| > Θ (paper: 20)"),
        &TeachingParams::theta);
    tstarLabel_ = new QLabel(this);
    tstarLabel_->setWordWrap(true);
    grid->addWidget(tstarLabel_, 11, 0, 1, 3);
}

ParameterPanel::Row ParameterPanel::addRow(QGridLayout* grid, int quantity, const QString& label,
                                           double lo, double hi, double step, int decimals,
                                           const QString& suffix) {
    const int row = quantity + 3;
    Row r{new QSlider(Qt::Horizontal, this), new QDoubleSpinBox(this), step};
    r.slider->setRange(static_cast<int>(std::lround(lo / step)),
                       static_cast<int>(std::lround(hi / step)));
    r.spin->setRange(lo, hi);
    r.spin->setDecimals(decimals);
    r.spin->setSingleStep(step);
    r.spin->setSuffix(suffix);
    r.spin->setKeyboardTracking(false);
    // Named for tests/ui/tst_screen_1280: the value beside each slider must show in full.
    static const char* const names[] = {"aValue", "fValue", "muValue", "dValue"};
    r.spin->setObjectName(QString::fromLatin1(names[quantity]));
    // As wide as its widest value with the unit, at any text size; the slider gives way.
    r.spin->setSizePolicy(QSizePolicy::Fixed, QSizePolicy::Fixed);
    grid->addWidget(new QLabel(label, this), row, 0);
    grid->addWidget(r.slider, row, 1);
    grid->addWidget(r.spin, row, 2);
    connect(r.slider, &QSlider::valueChanged, this, [this, r, quantity](int v) {
        {
            const QSignalBlocker block(r.spin);
            r.spin->setValue(v * r.step);
        }
        setValue(quantity, r.spin->value());
    });
    connect(r.spin, &QDoubleSpinBox::valueChanged, this, [this, r, quantity](double v) {
        {
            const QSignalBlocker block(r.slider);
            r.slider->setValue(static_cast<int>(std::lround(v / r.step)));
        }
        setValue(quantity, v);
    });
    return r;
}

// The exact values are kept apart from the widgets: a preset's wall width (2 g (0.099 s)^2)
// must not be rounded to the spin box's 0.1 mm, or t* would no longer be the paper's.
void ParameterPanel::setValue(int quantity, double v) {
    if (quiet_) return;
    switch (quantity) {
    case kA:
        values_.amplitude = v;
        break;
    case kF:
        values_.frequencyHz = v;
        break;
    case kMu:
        values_.mu = v;
        break;
    case kD:
        values_.wallWidthM = v * metresPerDisplayUnit(units_, LengthScale::Detail);
        break;
    }
    changed();
}

QDoubleSpinBox* ParameterPanel::addSpin(QGridLayout* grid, int row, const QString& label, double lo,
                                        double hi, double step, int decimals, const QString& suffix,
                                        const QString& tip, double TeachingParams::*field) {
    auto* spin = new QDoubleSpinBox(this);
    spin->setRange(lo, hi);
    spin->setSingleStep(step);
    spin->setDecimals(decimals);
    spin->setSuffix(suffix);
    spin->setToolTip(tip);
    spin->setKeyboardTracking(false);
    grid->addWidget(new QLabel(label, this), row, 0);
    grid->addWidget(spin, row, 1);
    connect(spin, &QDoubleSpinBox::valueChanged, this, [this, field](double v) {
        if (quiet_) return;
        values_.*field = v;
        changed();
    });
    return spin;
}

void ParameterPanel::setParams(const TeachingParams& p) {
    quiet_ = true;
    model_->setCurrentIndex(model_->findData(int(p.model)));
    fy_->setValue(p.fyHz);
    ayRatio_->setValue(p.ayRatio);
    theta_->setValue(p.theta);
    envelope_->setCurrentIndex(envelope_->findData(int(p.envelope)));
    scale_->setCurrentIndex(scale_->findData(int(p.scale)));
    rows_[kA].spin->setValue(p.amplitude);
    rows_[kF].spin->setValue(p.frequencyHz);
    rows_[kMu].spin->setValue(p.mu);
    rows_[kD].spin->setValue(p.wallWidthM / metresPerDisplayUnit(units_, LengthScale::Detail));
    limit_->setValue(p.limit);
    values_ = p;
    quiet_ = false;
    updatePlanarEnabled();
    updateTstarLabel();
}

void ParameterPanel::setUnitSystem(UnitSystem s) {
    units_ = s;
    const Row& d = rows_[kD];
    const bool us = s == UnitSystem::US;
    const double lo = us ? 2.0 : 50.0, hi = us ? 20.0 : 500.0; // about 5-50 cm either way
    quiet_ = true;
    d.slider->setRange(static_cast<int>(std::lround(lo / d.step)),
                       static_cast<int>(std::lround(hi / d.step)));
    d.spin->setRange(lo, hi);
    d.spin->setDecimals(us ? 3 : 1);
    d.spin->setSuffix(QLatin1Char(' ') + lengthSymbol(s, LengthScale::Detail));
    d.spin->setValue(values_.wallWidthM / metresPerDisplayUnit(s, LengthScale::Detail));
    quiet_ = false;
    updateTstarLabel();
}

QSlider* ParameterPanel::slider(Quantity q) const {
    return rows_[static_cast<int>(q)].slider;
}
QDoubleSpinBox* ParameterPanel::spinBox(Quantity q) const {
    return rows_[static_cast<int>(q)].spin;
}

void ParameterPanel::changed() {
    if (quiet_) return;
    values_.model = static_cast<TeachingModel>(model_->currentData().toInt());
    updatePlanarEnabled();
    values_.envelope = static_cast<EnvelopePreset>(envelope_->currentData().toInt());
    values_.scale = static_cast<TauScale>(scale_->currentData().toInt());
    values_.limit = limit_->value();
    updateTstarLabel();
    emit paramsChanged(values_);
}

void ParameterPanel::updatePlanarEnabled() {
    const bool planar = values_.model == TeachingModel::Planar;
    for (QDoubleSpinBox* s : {fy_, ayRatio_, theta_})
        s->setEnabled(planar);
}

void ParameterPanel::updateTstarLabel() {
    const double d = values_.wallWidthM;
    const bool us = units_ == UnitSystem::US;
    tstarLabel_->setText(
        tr("d = %1 %2,  t* = √(d/2g) = %3 s")
            .arg(d / metresPerDisplayUnit(units_, LengthScale::Detail), 0, 'f', us ? 3 : 1)
            .arg(lengthSymbol(units_, LengthScale::Detail))
            .arg(tstarFromWallWidth(d), 0, 'f', 4));
}

} // namespace kinstab::ui
