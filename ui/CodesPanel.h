// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Codes: which building codes to check and each code's own inputs (zone, soil or site class,
// force-reduction factor, importance). A code is checked when its box is ticked.

#include "core/codes/CodeCatalog.h"
#include "core/codes/CodeSet.h"
#include "ui/InputPanel.h"

class QCheckBox;
class QComboBox;
class QFormLayout;
class QGroupBox;

namespace kinstab::ui {

class NumberField;

class CodesPanel : public InputPanel {
    Q_OBJECT
public:
    explicit CodesPanel(QWidget* parent = nullptr);

    CodeSelection codes() const; // valid panel only
    void setCodes(const CodeSelection& c);

private:
    QGroupBox* group(CodeKey code, const QString& toolTip);
    NumberField* field(QFormLayout* form, const char* name, const QString& label,
                       const QString& unit, const QString& toolTip);
    QComboBox* combo(QFormLayout* form, const QString& label, const QStringList& items,
                     const QString& toolTip);
    void buildUbc1976();
    void buildAtc306();
    void buildUbc1997();
    void buildAsce7();
    void buildEc8();
    // One code's inputs from its fields, over the kept values the panel does not show.
    Ubc1976Inputs ubc1976Inputs() const;
    Atc306Inputs atc306Inputs() const;
    Ubc1997Inputs ubc1997Inputs() const;
    Asce7Inputs asce7Inputs() const;
    Eurocode8Inputs ec8Inputs() const;

    CodeSelection m_kept; // defaults for a code ticked on, and fields not shown
    QGroupBox *m_ubc76, *m_atc, *m_ubc97, *m_asce, *m_ec8;
    QComboBox* m_ubc76Zone;
    NumberField *m_ubc76K, *m_ubc76I, *m_ubc76Ts;
    QComboBox *m_atcArea, *m_atcSoil;
    NumberField *m_atcAa, *m_atcAv, *m_atcR;
    QComboBox *m_ubc97Zone, *m_ubc97Soil;
    NumberField *m_ubc97Na, *m_ubc97Nv, *m_ubc97I, *m_ubc97R;
    QComboBox *m_asceSite, *m_asceRisk;
    NumberField *m_asceSds, *m_asceSd1, *m_asceS1, *m_asceTl, *m_asceI, *m_asceR;
    QComboBox *m_ec8Ground, *m_ec8Type, *m_ec8Class;
    NumberField *m_ec8Agr, *m_ec8GammaI, *m_ec8Q, *m_ec8Beta;
    QCheckBox* m_ec8Regular;
};

} // namespace kinstab::ui
