// SPDX-License-Identifier: GPL-3.0-or-later
// ModelPanel, continued: the free-standing block's fields (core/rocking/BlockMapSettings.h).
// b and h are lengths shown in View → Units' system and kept in metres; μ and the restitution
// may be left empty (no sliding; Housner's value); the map's axes run from one step above 0 to
// their maxima.

#include "core/rocking/Block.h"
#include "ui/ModelPanel.h"
#include "ui/NumberField.h"

#include <QComboBox>
#include <QFormLayout>
#include <QLabel>

#include <cmath>

namespace kinstab::ui {

namespace {

QComboBox* equationsCombo(QWidget* parent) {
    auto* c = new QComboBox(parent);
    c->setObjectName(QStringLiteral("blockEquations"));
    c->addItem(ModelPanel::tr("exact"));
    c->addItem(ModelPanel::tr("linearised"));
    c->setToolTip(ModelPanel::tr("The exact equations of rocking, or the linearised ones of the "
                                 "closed forms (slender blocks). The other's boundary is drawn "
                                 "over the map."));
    return c;
}

QComboBox* pulseCombo(QWidget* parent) {
    auto* c = new QComboBox(parent);
    c->setObjectName(QStringLiteral("blockPulse"));
    for (PulseShape s : {PulseShape::HalfSine, PulseShape::OneSine, PulseShape::OneCosine,
                         PulseShape::Rectangular})
        c->addItem(QString::fromUtf8(pulseShapeName(s).data(),
                                     static_cast<int>(pulseShapeName(s).size())));
    c->setToolTip(ModelPanel::tr("The pulse of the map. Rectangular: ω_p/p stands for 2π/(p t₁)."));
    return c;
}

} // namespace

// b, h, the base's μ and the restitution.
void ModelPanel::buildBlockFields() {
    m_b = addField("blockHalfWidth", tr("Half-&width b:"), QString(),
                   tr("Half the width of the block's base (its rocking lever): α = atan(b/h)."));
    m_b->setLength(LengthScale::Structure, 1.0); // kept in metres
    m_b->setCheck(rangeCheck(kHalfWidthInput.range));
    m_h = addField("blockHalfHeight", tr("Half-&height h:"), QString(),
                   tr("Half the height of the block: R = √(b² + h²), p = √(3g / 4R)."));
    m_h->setLength(LengthScale::Structure, 1.0);
    m_h->setCheck(rangeCheck(kHalfHeightInput.range));
    m_mu = addField("blockMu", tr("μ (base):"), QString(),
                    tr("Coulomb friction at the base (static = kinetic). Empty: the base holds "
                       "the block, it rocks but never slides."));
    m_mu->setCheck(rangeCheck(kBlockMuInput.range));
    m_mu->setOptional(tr("none: never slides"));
    m_restitution =
        addField("blockRestitution", tr("Restitution η:"), QString(),
                 tr("Angular velocity kept at each impact. Empty: Housner's 1 − 1.5 sin²α "
                    "(angular momentum about the new corner)."));
    m_restitution->setCheck(rangeCheck(kRestitutionInput.range));
    m_restitution->setOptional(tr("Housner's"));
}

// The map's axes and points, and the note with α, p and η below them.
void ModelPanel::buildMapFields() {
    m_aMax = addField("mapAmplitudeMax", tr("a_p/(αg) up to:"), QString(),
                      tr("The map's amplitude axis runs from one step above 0 to this."));
    m_aMax->setCheck(rangeCheck(kMapAmplitudeMaxInput.range));
    m_wMax = addField("mapFrequencyMax", tr("ω_p/p up to:"), QString(),
                      tr("The map's frequency axis runs from one step above 0 to this."));
    m_wMax->setCheck(rangeCheck(kMapFrequencyMaxInput.range));
    m_points = addField("mapPoints", tr("Points per axis:"), QString(),
                        tr("101 × 101 points take about a second on two cores."));
    m_points->setCheck([](double v) {
        if (v != std::floor(v)) return tr("must be a whole number (got %1)").arg(v);
        return rangeCheck(kMapPointsInput.range)(v);
    });
    m_blockNote = new QLabel(this);
    m_blockNote->setWordWrap(true);
    form()->addRow(QString(), m_blockNote);
}

void ModelPanel::buildBlockRows() {
    buildBlockFields();
    m_equations = equationsCombo(this);
    form()->addRow(tr("Equations:"), m_equations);
    m_pulse = pulseCombo(this);
    form()->addRow(tr("Pulse:"), m_pulse);
    buildMapFields();
    for (QComboBox* c : {m_equations, m_pulse}) {
        c->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
        c->setMinimumContentsLength(12);
        connect(c, &QComboBox::currentIndexChanged, this, &InputPanel::changed);
    }
    connect(this, &InputPanel::changed, this, &ModelPanel::updateBlockNotes);
}

void ModelPanel::showBlock(const BlockMapSettings& s) {
    m_loadedBlock = s;
    m_b->setValue(s.block.halfWidth);
    m_h->setValue(s.block.halfHeight);
    m_mu->setOptionalValue(s.mu);
    m_restitution->setOptionalValue(s.restitution);
    m_equations->setCurrentIndex(s.equations == RockingEquations::Exact ? 0 : 1);
    m_pulse->setCurrentIndex(static_cast<int>(s.shape));
    m_aMax->setValue(s.amplitudeMax);
    m_wMax->setValue(s.frequencyMax);
    m_points->setValue(s.points);
    updateBlockNotes();
}

BlockMapSettings ModelPanel::blockSettings() const {
    BlockMapSettings s = m_loadedBlock;
    s.selected = isBlock();
    s.block.halfWidth = m_b->value().value_or(s.block.halfWidth);
    s.block.halfHeight = m_h->value().value_or(s.block.halfHeight);
    if (m_mu->isValid()) s.mu = m_mu->value();
    if (m_restitution->isValid()) s.restitution = m_restitution->value();
    s.equations =
        m_equations->currentIndex() == 0 ? RockingEquations::Exact : RockingEquations::Linearised;
    s.shape = static_cast<PulseShape>(m_pulse->currentIndex());
    s.amplitudeMax = m_aMax->value().value_or(s.amplitudeMax);
    s.frequencyMax = m_wMax->value().value_or(s.frequencyMax);
    s.points = static_cast<int>(m_points->value().value_or(s.points));
    return s;
}

// α, p and the restitution in use, so the dimensionless axes have numbers behind them.
void ModelPanel::updateBlockNotes() {
    if (!m_blockNote || !m_b->isValid() || !m_h->isValid()) {
        if (m_blockNote) m_blockNote->clear();
        return;
    }
    const Block b{*m_b->value(), *m_h->value()};
    const double alpha = blockAlpha(b);
    const double eta = m_restitution->value().value_or(housnerRestitution(alpha));
    m_blockNote->setText(tr("α = %1 rad, p = %2 rad/s, η = %3")
                             .arg(alpha, 0, 'f', 4)
                             .arg(blockFrequency(b), 0, 'f', 3)
                             .arg(eta, 0, 'f', 3));
}

} // namespace kinstab::ui
