// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/ExcitationPanel.h"

#include "ui/EnvelopeChart.h"
#include "ui/NumberField.h"
#include "ui/RecordInput.h"

#include <QComboBox>
#include <QFormLayout>
#include <QLabel>

#include <cmath>

namespace kinstab::ui {

namespace {
constexpr int customIndex = 3;
const EnvelopePreset presets[] = {EnvelopePreset::Fast, EnvelopePreset::Moderate,
                                  EnvelopePreset::Slow};
} // namespace

ExcitationPanel::ExcitationPanel(QWidget* parent)
    : InputPanel(parent), m_preset(new QComboBox(this)), m_scale(new QComboBox(this)),
      m_times(new QLabel(this)), m_chart(new EnvelopeChart(this)), m_source(new QComboBox(this)),
      m_record(new RecordInput(this)) {
    buildEnvelopeRows();
    m_scale->addItems({tr("τ_max (default)"), tr("τ_rise"), tr("τ_dur"), tr("1 (γc = 1/τc)")});
    m_scale->setToolTip(tr("Reference time τ_ref in the collapse factor γc = τ_ref / τc. With "
                           "τ_max the surfaces of the three envelopes look most alike."));
    form()->addRow(tr("γc &scale:"), m_scale);
    m_times->setWordWrap(true);
    form()->addRow(m_times);
    form()->addRow(m_chart);
    form()->addRow(m_record);
    track(m_record->peakField(), tr("Target peak:"));
    connectRows();
    setEnvelope(Envelope::fromPreset(EnvelopePreset::Moderate));
    updateSource();
}

void ExcitationPanel::buildEnvelopeRows() {
    m_source->setObjectName("excitationSource");
    m_source->addItems({tr("Enveloped sine"), tr("Record")});
    m_source->setToolTip(tr("The floor acceleration: the paper's enveloped sine over an (A, f) "
                            "grid, or a recorded accelerogram (optionally through the floor "
                            "filter) scaled to a peak."));
    form()->addRow(tr("S&ource:"), m_source);
    m_preset->addItems({tr("Fast rising (Table 4)"), tr("Moderately rising (Table 4)"),
                        tr("Slowly rising (Table 4)"), tr("Custom α, β")});
    m_preset->setToolTip(tr("Shape of the floor-acceleration envelope. The paper's three presets "
                            "(Table 4); a moderately rising envelope suits a soft-soil site."));
    form()->addRow(tr("&Envelope:"), m_preset);
    m_alpha = addField("alpha", tr("α:"), tr("1/s"),
                       tr("Decay rate of the envelope e(t) = exp(−αt) − exp(−βt): smaller α "
                          "means longer strong shaking."));
    m_beta = addField("beta", tr("β:"), tr("1/s"),
                      tr("Rise rate of the envelope: larger β means a faster build-up. Must "
                         "exceed α."));
    m_alpha->setCheck(rangeCheck(kAlphaInput.range));
    m_beta->setCheck([this](double b) {
        if (const QString e = rangeCheck(kBetaInput.range)(b); !e.isEmpty()) return e;
        const auto a = m_alpha->value();
        if (a && b <= *a) return tr("must exceed α = %1 (got %2)").arg(*a).arg(b);
        return QString();
    });
    connect(m_alpha, &NumberField::edited, m_beta, &NumberField::revalidate);
}

// A change of source or preset shows its rows; every change updates the times shown.
void ExcitationPanel::connectRows() {
    connect(m_record, &RecordInput::changed, this, &InputPanel::changed);
    connect(m_source, &QComboBox::currentIndexChanged, this, [this] {
        updateSource();
        emit changed();
    });
    connect(m_preset, &QComboBox::currentIndexChanged, this, [this] {
        updatePreset();
        emit changed();
    });
    connect(m_scale, &QComboBox::currentIndexChanged, this, &InputPanel::changed);
    connect(this, &InputPanel::changed, this, &ExcitationPanel::updateTimes);
}

void ExcitationPanel::updateSource() {
    const bool record = usesRecord();
    for (QWidget* w : std::initializer_list<QWidget*>{m_preset, m_alpha, m_beta, m_times, m_chart})
        form()->setRowVisible(w, !record);
    form()->setRowVisible(m_record, record);
    m_record->peakField()->setEnabled(record);
    updatePreset();
}

bool ExcitationPanel::usesRecord() const {
    return m_source->currentIndex() == 1;
}

void ExcitationPanel::setUsesRecord(bool on) {
    m_source->setCurrentIndex(on ? 1 : 0);
}

std::optional<RecordExcitation> ExcitationPanel::record() const {
    return usesRecord() ? m_record->record() : std::nullopt;
}

void ExcitationPanel::setRecord(const std::optional<RecordExcitation>& r) {
    if (r) m_record->setRecord(*r);
    setUsesRecord(r.has_value());
}

QStringList ExcitationPanel::extraProblems() const {
    // An invalid peak field is a tracked field, listed with the others already.
    if (!usesRecord() || m_record->isReady() || !m_record->peakField()->isValid()) return {};
    return {m_record->problem()};
}

void ExcitationPanel::updatePreset() {
    const int i = m_preset->currentIndex();
    const bool custom = i == customIndex;
    if (!custom) {
        const Envelope e = Envelope::fromPreset(presets[i]);
        m_alpha->setValue(e.alpha);
        m_beta->setValue(e.beta);
    }
    m_alpha->setEnabled(custom && !usesRecord());
    m_beta->setEnabled(custom && !usesRecord());
    updateTimes();
}

Envelope ExcitationPanel::envelope() const {
    const int i = m_preset->currentIndex();
    if (i != customIndex) return Envelope::fromPreset(presets[i]);
    Envelope e;
    e.alpha = m_alpha->value().value_or(e.alpha);
    e.beta = m_beta->value().value_or(e.beta);
    e.preset.reset();
    return e;
}

void ExcitationPanel::setEnvelope(const Envelope& e) {
    m_alpha->setValue(e.alpha);
    m_beta->setValue(e.beta);
    m_preset->setCurrentIndex(e.preset ? static_cast<int>(*e.preset) : customIndex);
    updatePreset();
}

TauScale ExcitationPanel::scale() const {
    const TauScale s[] = {TauScale::TauMax, TauScale::TauRise, TauScale::TauDur, TauScale::One};
    return s[m_scale->currentIndex()];
}

void ExcitationPanel::setScale(TauScale s) {
    const int index[] = {1, 0, 2, 3}; // by enum order TauRise, TauMax, TauDur, One
    m_scale->setCurrentIndex(index[static_cast<int>(s)]);
}

void ExcitationPanel::setTstar(double tstar) {
    m_tstar = tstar;
    updateTimes();
}

void ExcitationPanel::updateTimes() {
    if (!fieldsValid()) {
        m_times->clear();
        return;
    }
    const Envelope e = envelope();
    const CharacteristicTimes c = e.computedTimes(m_tstar);
    QString text = tr("Computed: τ_rise %1, τ_max %2, τ_dur %3")
                       .arg(c.tauRise, 0, 'f', 2)
                       .arg(c.tauMax, 0, 'f', 2)
                       .arg(c.tauDur, 0, 'f', 2);
    if (e.preset) {
        const CharacteristicTimes t = table4Times(*e.preset);
        text += tr("<br>Table 4 (used for γc): τ_rise %1, τ_max %2, τ_dur %3")
                    .arg(t.tauRise, 0, 'f', 2)
                    .arg(t.tauMax, 0, 'f', 2)
                    .arg(t.tauDur, 0, 'f', 2);
    }
    m_times->setText(text);
    m_chart->setEnvelope(e, m_tstar);
}

} // namespace kinstab::ui
