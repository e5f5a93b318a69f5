// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Sliders (with exact spin boxes) for A, f, mu and the wall width, plus the envelope, the
// gamma_c scaling and the bearing limit. Every change emits paramsChanged at once: a run takes
// well under a frame, so the view re-runs while the slider moves.

#include "ui/teaching/TeachingRun.h"

#include <QWidget>

class QComboBox;
class QDoubleSpinBox;
class QGridLayout;
class QLabel;
class QSlider;

#include "ui/Units.h"

namespace kinstab::ui {

class ParameterPanel : public QWidget {
    Q_OBJECT
public:
    explicit ParameterPanel(QWidget* parent = nullptr);
    TeachingParams params() const { return values_; }
    void setParams(const TeachingParams& p); // no paramsChanged
    // The wall width in mm (SI) or in (US customary); the value itself is unchanged.
    void setUnitSystem(UnitSystem s);

    // For tests and the main window: the slider of one quantity.
    enum class Quantity { Amplitude, Frequency, Mu, WallWidth };
    QSlider* slider(Quantity q) const;
    QDoubleSpinBox* spinBox(Quantity q) const;

signals:
    void paramsChanged(const kinstab::ui::TeachingParams& p);

private:
    struct Row {
        QSlider* slider;
        QDoubleSpinBox* spin;
        double step;
    };
    void buildChoices(QGridLayout* grid);
    void buildNumberRows(QGridLayout* grid);
    void buildPlanarRows(QGridLayout* grid);
    Row addRow(QGridLayout* grid, int quantity, const QString& label, double lo, double hi,
               double step, int decimals, const QString& suffix);
    QDoubleSpinBox* addSpin(QGridLayout* grid, int row, const QString& label, double lo, double hi,
                            double step, int decimals, const QString& suffix, const QString& tip,
                            double TeachingParams::*field);
    void updatePlanarEnabled();
    void setValue(int quantity, double v);
    void changed();
    void updateTstarLabel();

    Row rows_[4];
    QComboBox* model_;
    QComboBox* envelope_;
    QComboBox* scale_;
    QDoubleSpinBox* limit_;
    QDoubleSpinBox* fy_;
    QDoubleSpinBox* ayRatio_;
    QDoubleSpinBox* theta_;
    QLabel* tstarLabel_;
    TeachingParams values_;
    UnitSystem units_ = UnitSystem::SI;
    bool quiet_ = false;
};

} // namespace kinstab::ui
