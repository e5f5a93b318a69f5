// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Grid: the ranges and steps of amplitude A and frequency f that a sweep covers.

#include "core/sweep/Grid.h"
#include "ui/InputPanel.h"

class QLabel;

namespace kinstab::ui {

class NumberField;

struct GridRanges {
    double aFrom = 0.6, aTo = 1.5, aStep = 0.025;
    double fFrom = 0.25, fTo = 3.0, fStep = 0.125;
};

class GridPanel : public InputPanel {
    Q_OBJECT
public:
    explicit GridPanel(QWidget* parent = nullptr);

    GridRanges ranges() const; // valid panel only
    void setRanges(const GridRanges& r);
    SweepGrid grid() const;
    // Shows a grid of values as from/to/step; false when it was not evenly spaced.
    bool setGrid(const SweepGrid& g);

private:
    void updateCount();
    QString rangeProblem(double from, double to, double step, const QString& what) const;

    NumberField* m_aFrom;
    NumberField* m_aTo;
    NumberField* m_aStep;
    NumberField* m_fFrom;
    NumberField* m_fTo;
    NumberField* m_fStep;
    QLabel* m_count;
};

} // namespace kinstab::ui
