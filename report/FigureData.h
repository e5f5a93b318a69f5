// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What the report's figures draw: γc on an (A, f) grid and the design overlays. Plain values,
// filled from a core SweepResult and the design check.

#include <QColor>
#include <QString>

#include <optional>
#include <string>
#include <vector>

namespace kinstab {
struct SweepResult;
}

namespace kinstab::report {

struct SurfaceData {
    std::vector<double> amplitudes;  // g, ascending
    std::vector<double> frequencies; // Hz, ascending
    std::vector<double> gamma;       // γc, row-major: gamma[i * frequencies + j]; NaN: not run

    double at(std::size_t i, std::size_t j) const { return gamma[i * frequencies.size() + j]; }
    double maxGamma() const; // largest finite value, 0 when none
};

SurfaceData surfaceFromSweep(const SweepResult& r, double tauRef);

struct CodeMark {
    QString label;        // "UBC 1976"
    double ratio = 0;     // F_top / w_top
    double frequency = 0; // Hz: 1 / T of this code's period (the design point)
    QColor colour;        // the code's colour, the GUI's too (core/codes/CodeCatalog.h)
};

struct DesignOverlay {
    std::vector<double> critFrequencies;              // Hz
    std::vector<std::optional<double>> critAmplitude; // A_crit(f), nullopt: none found
    std::vector<CodeMark> codes;
    std::optional<double> designFrequency; // 1 / T
};

struct SliceData {
    std::vector<double> amplitudes; // g
    std::vector<double> gamma;      // γc(A) at one frequency
    double frequency = 0;           // Hz
    std::optional<double> aCrit;
};

} // namespace kinstab::report
