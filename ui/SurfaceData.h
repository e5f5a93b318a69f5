// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What the γc surface shows, as plain values: the grid, γc per point (NaN where not yet
// computed) and the overlays (code ratios, the building's frequency, A_crit(f)).

#include "core/sweep/Sweep.h"

#include <QColor>
#include <QString>

#include <optional>
#include <vector>

namespace kinstab::ui {

struct GammaGrid {
    std::vector<double> amplitudes;  // g (columns, X axis)
    std::vector<double> frequencies; // Hz (rows, Z axis)
    std::vector<double> gamma;       // row-major by amplitude: gamma[i * nf + j]; NaN = not done
    QString gammaTitle = QStringLiteral("γc");

    double at(std::size_t ai, std::size_t fi) const { return gamma[ai * frequencies.size() + fi]; }
    bool empty() const { return amplitudes.empty() || frequencies.empty(); }
};

// γc with NaN for points not computed (a running or cancelled sweep).
GammaGrid gammaGrid(const SweepResult& r, double tauRef);

struct CodeRatio {
    QString name; // "UBC 1976"
    double ratio; // top-floor lateral force / weight, g
    QColor color;
};

struct SurfaceOverlays {
    std::vector<CodeRatio> codes;
    std::optional<double> buildingFrequency;      // 1/T, Hz
    std::vector<std::pair<double, double>> aCrit; // (f, A_crit) where something collapses
};

// Linear interpolation of γc along amplitude at one frequency row; NaN outside or unknown.
double gammaAtAmplitude(const GammaGrid& g, std::size_t fi, double amplitude);
// Nearest frequency row to f (grid not empty).
std::size_t nearestFrequency(const GammaGrid& g, double f);

} // namespace kinstab::ui
