// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Model: the 1-DOF slab (across the walls), the planar 2-DOF slab with vertical motion
// (docs/user-guide.md "model (1-DOF / planar)", Furgerson 1980 ch. VI), or a free-standing block
// and its overturning map (ModelPanelBlock.cpp). Each model's fields are shown, checked and gate
// Run only when it is chosen.

#include "core/base/ModelKind.h"
#include "core/rocking/BlockMapSettings.h"
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
    bool isBlock() const; // "Free-standing block": Run computes its overturning map
    // The slab model (the last one chosen while the block is shown).
    ModelKind model() const;
    // The planar settings shown (valid fields only; the others keep their last loaded value).
    PlanarSettings settings() const;
    void load(ModelKind model, const PlanarSettings& s, const BlockMapSettings& block = {});
    // The block's settings shown (valid fields only; the others keep their last loaded value),
    // selected when the block is the chosen model.
    BlockMapSettings blockSettings() const;

    // For tests: the vertical record's path field and its message.
    QLineEdit* verticalPathEdit() const { return m_path; }
    QString verticalError() const { return m_verticalError; }

protected:
    QStringList extraProblems() const override;

private:
    void buildPlanarRows();
    void buildBlockRows(); // ModelPanelBlock.cpp
    void buildBlockFields();
    void buildMapFields();
    void showBlock(const BlockMapSettings& s);
    void updateMode();
    void updateBlockNotes();
    void checkVerticalFile();
    void browse();

    PlanarSettings m_loaded;
    BlockMapSettings m_loadedBlock;
    int m_slabIndex = 0; // the slab model chosen last (0: 1-DOF, 1: planar)
    NumberField* m_b = nullptr;
    NumberField* m_h = nullptr;
    NumberField* m_mu = nullptr;
    NumberField* m_restitution = nullptr;
    QComboBox* m_equations = nullptr;
    QComboBox* m_pulse = nullptr;
    NumberField* m_aMax = nullptr;
    NumberField* m_wMax = nullptr;
    NumberField* m_points = nullptr;
    QLabel* m_blockNote = nullptr;
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
