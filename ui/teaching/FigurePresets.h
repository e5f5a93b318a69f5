// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One-click settings that reproduce the figures of Furgerson (1980), ch. IV: the gamma_c
// surfaces of Figs. 28-33 (three envelopes, gamma_c = tau_max / tau_c or tau_rise / tau_c),
// Fig. 34 (tau_c against A at f = 0.75 Hz) and Fig. 35 (delta(tau) with the envelope for
// A = 1.0, f = 1.125 Hz). All at the paper's t* = 0.099 s, mu = 0.6, bearing d/2.

#include "ui/teaching/TeachingRun.h"

#include <QString>

#include <vector>

namespace kinstab::ui {

// What the small "where am I" panel shows.
enum class MapMode { Surface, Slice };

struct MapRange {
    double aMin = 0.5, aMax = 1.5;  // g
    double fMin = 0.25, fMax = 2.0; // Hz
    bool operator==(const MapRange&) const = default;
};

struct FigurePreset {
    QString id;      // "fig29"
    QString title;   // in plain words what happens, shown in the preset list
    QString figure;  // "Fig. 29": the secondary note after the title
    QString caption; // what the figure shows, after the paper's caption
    TeachingParams params;
    MapMode mode = MapMode::Surface;
    MapRange range;
};

// The paper's computed range: 0.7 <= A <= 1.15, 0.5 <= f <= 1.125 (ch. IV, "Results").
inline constexpr MapRange kPaperRange{0.7, 1.15, 0.5, 1.125};

// Ch. VI: 0.5 <= A_x <= 1.15, 0.5 <= f_x <= 2.0.
inline constexpr MapRange kPlanarRange{0.5, 1.15, 0.5, 2.0};

const std::vector<FigurePreset>& figurePresets();
const FigurePreset* findFigurePreset(const QString& id);
// "title · Fig. N", as the preset list shows it.
QString presetListText(const FigurePreset& p);

} // namespace kinstab::ui
