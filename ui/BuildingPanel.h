// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Building: what every code needs (units, stories, height, plan dimension, period entered or
// estimated by each code's formula, lateral system, occupancy). Story weights and heights that
// a project file gives are kept as they are (uniform when empty).

#include "core/codes/Building.h"
#include "ui/InputPanel.h"

class QCheckBox;
class QComboBox;
class QLabel;

namespace kinstab::ui {

class NumberField;
class TextField;

class BuildingPanel : public InputPanel {
    Q_OBJECT
public:
    explicit BuildingPanel(QWidget* parent = nullptr);

    Building building() const;  // valid panel only
    QString systemNote() const; // what a change of system drives (shown under it)
    void setBuilding(const Building& b);

protected:
    QStringList extraProblems() const override; // the name's (ui/TextField.h)

private:
    void buildNameRow();
    void buildSizeFields(); // stories, height, plan dimension
    void buildPeriodRows(); // estimate by formula, period, the formulas' periods
    void buildUseRows();    // system and occupancy
    void updateEstimate();

    Building m_kept;                      // story weights and heights from the file
    LengthUnit m_unit = LengthUnit::Feet; // the file's; lengths are shown in View → Units
    TextField* m_name;
    NumberField* m_stories;
    NumberField* m_height;
    NumberField* m_dimension;
    QCheckBox* m_estimate;
    NumberField* m_period;
    QLabel* m_estimates;
    QComboBox* m_system;
    QLabel* m_systemNote; // what a change of system drives, given what is entered
    QComboBox* m_occupancy;
};

} // namespace kinstab::ui
