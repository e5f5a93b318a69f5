// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Excitation: one of the paper's envelope presets (Table 4) or a user alpha/beta, with a plot
// of the envelope and its characteristic times; or a record (RecordInput: file, preview, floor
// filter, target peak) instead of the enveloped sine (docs/user-guide.md).

#include "core/excitation/Envelope.h"
#include "core/excitation/RecordExcitation.h"
#include "ui/InputPanel.h"

#include <optional>

class QComboBox;
class QLabel;

namespace kinstab::ui {

class EnvelopeChart;
class NumberField;
class RecordInput;

class ExcitationPanel : public InputPanel {
    Q_OBJECT
public:
    explicit ExcitationPanel(QWidget* parent = nullptr);

    Envelope envelope() const; // valid panel only
    void setEnvelope(const Envelope& e);
    TauScale scale() const;
    void setScale(TauScale s);
    // The time scale the characteristic times are shown in.
    void setTstar(double tstar);

    // Record instead of the enveloped sine: none while the source is the sine.
    bool usesRecord() const;
    std::optional<RecordExcitation> record() const;
    void setRecord(const std::optional<RecordExcitation>& r); // none: the sine
    void setUsesRecord(bool on);
    RecordInput* recordInput() const { return m_record; }

protected:
    // With a record: a readable record file (its field shows the reason).
    QStringList extraProblems() const override;

private:
    void buildEnvelopeRows(); // source, envelope, α and β
    void connectRows();
    void updateSource();
    void updatePreset();
    void updateTimes();

    double m_tstar = 0.099;
    QComboBox* m_preset;
    NumberField* m_alpha;
    NumberField* m_beta;
    QComboBox* m_scale;
    QLabel* m_times;
    EnvelopeChart* m_chart;
    QComboBox* m_source;
    RecordInput* m_record;
};

} // namespace kinstab::ui
