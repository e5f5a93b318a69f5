// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Slab & walls: the wall width (or t* directly), the bearing limit, the friction coefficient
// and the solver. Everything of the 1-DOF case except the excitation.

#include "core/slab/Slab1DCase.h"
#include "ui/InputPanel.h"

#include <optional>

class QComboBox;
class QLabel;

namespace kinstab::ui {

class NumberField;

class SlabPanel : public InputPanel {
    Q_OBJECT
public:
    explicit SlabPanel(QWidget* parent = nullptr);

    // Writes t*, mu, limit and solver into c (valid panel only).
    void apply(Slab1DCase& c) const;
    // Shows c; when wallWidthM is given the panel is in wall-width mode.
    void load(const Slab1DCase& c, std::optional<double> wallWidthM);
    std::optional<double> wallWidthMetres() const; // nullopt in t* mode
    // The line under the fields (t* from d, or d from t*), in the fields' units.
    void updateDerived();

public slots:
    void useMu(double mu); // from the friction calibration panel

private:
    void updateMode();

    QComboBox* m_mode;
    NumberField* m_width;
    NumberField* m_tstar;
    QLabel* m_derived;
    NumberField* m_limit;
    NumberField* m_mu;
    QComboBox* m_solver;
};

} // namespace kinstab::ui
