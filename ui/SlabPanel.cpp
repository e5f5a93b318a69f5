// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/SlabPanel.h"

#include "core/base/InputLimits.h"
#include "core/slab/SlabInputs.h"
#include "ui/NumberField.h"

#include <QComboBox>
#include <QFormLayout>
#include <QLabel>

#include <cmath>

namespace kinstab::ui {

namespace {
constexpr double inch = 0.0254;
}

SlabPanel::SlabPanel(QWidget* parent)
    : InputPanel(parent), m_mode(new QComboBox(this)), m_derived(new QLabel(this)),
      m_solver(new QComboBox(this)) {
    m_mode->addItem(tr("Wall width d"));
    m_mode->addItem(tr("Characteristic time t*"));
    m_mode->setToolTip(
        tr("Enter the supporting wall's width d (t* = √(d / 2g) follows), or t* itself."));
    form()->addRow(tr("Input:"), m_mode);
    m_width = addField("wallWidth", tr("Wall &width d:"), QString(),
                       tr("Actual width of the wall the slab bears on (an 8-inch block wall is "
                          "7⅝ in). Sets the time scale t* = √(d / 2g) and the length scale d/2."));
    m_width->setLength(LengthScale::Detail, 1.0); // kept in metres, shown in mm or in
    const Range inches = kWallWidthInput.range;   // the field keeps metres
    m_width->setCheck(rangeCheck(inches.lo * 0.0254, inches.hi * 0.0254));
    m_tstar = addField("tstar", tr("t*:"), tr("s"),
                       tr("Characteristic time t* = √(d / 2g): the time a block takes to fall "
                          "half its width under gravity. The paper uses 0.099 s."));
    m_tstar->setCheck(rangeCheck(kTstarInput.range));
    form()->addRow(QString(), m_derived);
    m_limit = addField("limit", tr("&Bearing / (d/2):"), QString(),
                       tr("Bearing length over half the wall width. The slab falls when its "
                          "slip relative to the wall exceeds the bearing length; the paper "
                          "takes bearing = d/2, i.e. 1."));
    m_limit->setCheck(rangeCheck(kLimitInput.range));
    m_mu = addField("mu", tr("Friction &μ:"), QString(),
                    tr("Coulomb friction coefficient between slab and wall after the mortar "
                       "joint has cracked. Masonry triplet tests give 0.55–0.66; the paper "
                       "uses 0.6. The slab cannot slip while |a| < μ g."));
    m_mu->setCheck(rangeCheck(kMuInput.range));
    m_solver->addItem(tr("Exact (event-driven)"));
    m_solver->addItem(tr("Paper RK4 (H = T/16)"));
    m_solver->setToolTip(tr("Exact: closed-form motion between stick/slip events (default).\n"
                            "Paper RK4: the 1980 report's fixed-step integrator, for comparison."));
    form()->addRow(tr("Solver:"), m_solver);

    connect(m_mode, &QComboBox::currentIndexChanged, this, [this] {
        updateMode();
        emit changed();
    });
    connect(m_solver, &QComboBox::currentIndexChanged, this, &InputPanel::changed);
    connect(m_width, &NumberField::edited, this, &SlabPanel::updateDerived);
    connect(m_tstar, &NumberField::edited, this, &SlabPanel::updateDerived);
    load(Slab1DCase{}, 7.625 * inch);
}

void SlabPanel::updateMode() {
    const bool byWidth = m_mode->currentIndex() == 0;
    m_width->setEnabled(byWidth);
    m_tstar->setEnabled(!byWidth);
    updateDerived();
}

// One wall width per case: the greyed field shows the width the entered t* stands for
// (d = 2g t*²), as Teaching and the report do, never a width left over from another case.
void SlabPanel::updateDerived() {
    if (const auto d = wallWidthMetres()) {
        // Greyed, to 0.1 ms as the line below says it (not 0.08745211031 for a 150 mm wall);
        // the case takes t* from d itself (apply()).
        m_tstar->setValue(std::round(tstarFromWallWidth(*d) * 1e4) / 1e4);
        m_derived->setText(tr("t* = √(d / 2g) = %1 s").arg(tstarFromWallWidth(*d), 0, 'f', 4));
        return;
    }
    const auto t = m_mode->currentIndex() == 1 ? m_tstar->value() : std::nullopt;
    if (t) m_width->setValue(wallWidthFromTstar(*t));
    m_derived->setText(
        t ? tr("d = 2g t*² = %1 %2")
                .arg(QString::fromStdString(lengthText(wallWidthFromTstar(*t),
                                                       m_width->unitSystem(), LengthScale::Detail)),
                     lengthSymbol(m_width->unitSystem(), LengthScale::Detail))
          : QString());
}

std::optional<double> SlabPanel::wallWidthMetres() const {
    if (m_mode->currentIndex() != 0) return std::nullopt;
    return m_width->value();
}

void SlabPanel::apply(Slab1DCase& c) const {
    const auto d = wallWidthMetres();
    c.tstar = d ? tstarFromWallWidth(*d) : m_tstar->value().value_or(c.tstar);
    c.slab.limit = m_limit->value().value_or(c.slab.limit);
    c.slab.mu = m_mu->value().value_or(c.slab.mu);
    c.solver = m_solver->currentIndex() == 0 ? SolverKind::Exact : SolverKind::Paper;
}

void SlabPanel::load(const Slab1DCase& c, std::optional<double> wallWidthM) {
    m_mode->setCurrentIndex(wallWidthM ? 0 : 1);
    if (wallWidthM) m_width->setValue(*wallWidthM);
    m_tstar->setValue(c.tstar);
    m_limit->setValue(c.slab.limit);
    m_mu->setValue(c.slab.mu);
    m_solver->setCurrentIndex(c.solver == SolverKind::Exact ? 0 : 1);
    updateMode();
}

void SlabPanel::useMu(double mu) {
    m_mu->setValue(mu);
}

} // namespace kinstab::ui
