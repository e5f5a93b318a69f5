// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Fourier amplitude spectrum of an accelerogram, normalized so that its largest component is 1
// (the paper's Figs. 25-26: "the modulus of the Fourier coefficients normalized so that the
// largest component is 1 vs. frequency"). Radix-2 FFT of the record padded with zeros.

#include <cstddef>
#include <vector>

namespace kinstab {

struct AmplitudeSpectrum {
    std::vector<double> frequency; // Hz, k / (N dt) for k = 0 .. N/2
    std::vector<double> amplitude; // |X_k| / max |X|
    double df = 0;                 // Hz, bin width
    std::size_t points = 0;        // N: the transform length after padding
};

struct SpectrumPeak {
    double frequency = 0; // Hz
    double amplitude = 0; // normalized
};

// Transform length: the next power of two at or above x.size() (at least 2).
AmplitudeSpectrum amplitudeSpectrum(const std::vector<double>& x, double dt);
// The `count` largest local maxima, largest first.
std::vector<SpectrumPeak> spectrumPeaks(const AmplitudeSpectrum& s, std::size_t count);
// Share of sum |X|^2 within [fLo, fHi]: how concentrated the motion is around a frequency.
double bandEnergyFraction(const AmplitudeSpectrum& s, double fLo, double fHi);

} // namespace kinstab
