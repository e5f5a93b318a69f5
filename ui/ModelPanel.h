// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Model: the 1-DOF slab (across the walls) or the planar 2-DOF slab with vertical motion
// (docs/user-guide.md "model (1-DOF / planar)", Furgerson 1980 ch. VI). The planar fields (f_y,
// A_y/A_x, Θ, normalization, vertical motion) are shown, checked and gate Run only when planar is
// chosen.

#include "core/base/ModelKind.h"
#include "core/slab/PlanarSettings.h"
#include "ui/InputPanel.h"

#include <string>

class QComboBox;
class QLabel;
class QLineEdit;
class QPushButton;

namespace kinstab::ui {

class NumberField;

class ModelPanel : public InputPanel {
    Q_OBJECT
public:
    explicit ModelPanel(QWidget* parent = nullptr);

    bool isPlanar() const;
    ModelKind model() const;
    // The planar settings shown (valid fields only; the others keep their last loaded value).
    PlanarSettings settings() const;
    void load(ModelKind model, const PlanarSettings& s);

    // For tests: the vertical record's path field and its message.
    QLineEdit* verticalPathEdit() const { return m_path; }
    QString verticalError() const { return m_verticalError; }

protected:
    QStringList extraProblems() const override;

private:
    void buildPlanarRows();
    void updateMode();
    void checkVerticalFile();
    void browse();

    PlanarSettings m_loaded;
    QComboBox* m_model;
    NumberField* m_fy;
    NumberField* m_ratio;
    NumberField* m_theta;
    QComboBox* m_normalization;
    QComboBox* m_vertical;
    QWidget* m_fileRow;
    QLineEdit* m_path;
    QPushButton* m_browse;
    QLabel* m_pathError;
    QLabel* m_note;
    QString m_verticalError;
};

} // namespace kinstab::ui
