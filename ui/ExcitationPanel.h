#pragma once
// Excitation: one of the paper's envelope presets (Table 4) or a user alpha/beta, with a plot
// of the envelope and its characteristic times.

#include "core/excitation/Envelope.h"
#include "ui/InputPanel.h"

class QComboBox;
class QLabel;

namespace kinstab::ui {

class EnvelopeChart;
class NumberField;

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

private:
    void updatePreset();
    void updateTimes();

    double m_tstar = 0.099;
    QComboBox* m_preset;
    NumberField* m_alpha;
    NumberField* m_beta;
    QComboBox* m_scale;
    QLabel* m_times;
    EnvelopeChart* m_chart;
};

} // namespace kinstab::ui
