// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/excitation/FourierSpectrum.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>

namespace kinstab {

namespace {

// In-place iterative Cooley-Tukey FFT; x.size() is a power of two.
void fft(std::vector<std::complex<double>>& x) {
    const std::size_t n = x.size();
    for (std::size_t i = 1, j = 0; i < n; ++i) { // bit-reversal permutation
        std::size_t bit = n >> 1;
        for (; j & bit; bit >>= 1)
            j ^= bit;
        j ^= bit;
        if (i < j) std::swap(x[i], x[j]);
    }
    for (std::size_t len = 2; len <= n; len <<= 1) {
        const double angle = -2.0 * std::numbers::pi / static_cast<double>(len);
        for (std::size_t i = 0; i < n; i += len)
            for (std::size_t k = 0; k < len / 2; ++k) {
                // Twiddle computed directly (not by repeated multiplication) to keep rounding low.
                const std::complex<double> w = std::polar(1.0, angle * static_cast<double>(k));
                const std::complex<double> u = x[i + k], v = x[i + k + len / 2] * w;
                x[i + k] = u + v;
                x[i + k + len / 2] = u - v;
            }
    }
}

} // namespace

AmplitudeSpectrum amplitudeSpectrum(const std::vector<double>& x, double dt) {
    std::size_t n = 2;
    while (n < x.size())
        n <<= 1;
    std::vector<std::complex<double>> z(n);
    std::copy(x.begin(), x.end(), z.begin());
    fft(z);
    AmplitudeSpectrum s;
    s.points = n;
    s.df = 1.0 / (static_cast<double>(n) * dt);
    for (std::size_t k = 0; k <= n / 2; ++k) {
        s.frequency.push_back(static_cast<double>(k) * s.df);
        s.amplitude.push_back(std::abs(z[k]));
    }
    const double top = *std::max_element(s.amplitude.begin(), s.amplitude.end());
    if (top > 0.0)
        for (double& a : s.amplitude)
            a /= top;
    return s;
}

std::vector<SpectrumPeak> spectrumPeaks(const AmplitudeSpectrum& s, std::size_t count) {
    std::vector<SpectrumPeak> peaks;
    const std::size_t n = s.amplitude.size();
    for (std::size_t k = 0; k < n; ++k) {
        const double a = s.amplitude[k];
        const bool left = k == 0 || a > s.amplitude[k - 1];
        const bool right = k + 1 == n || a >= s.amplitude[k + 1];
        if (left && right && a > 0.0) peaks.push_back({s.frequency[k], a});
    }
    std::sort(peaks.begin(), peaks.end(),
              [](const auto& p, const auto& q) { return p.amplitude > q.amplitude; });
    if (peaks.size() > count) peaks.resize(count);
    return peaks;
}

double bandEnergyFraction(const AmplitudeSpectrum& s, double fLo, double fHi) {
    double in = 0.0, all = 0.0;
    for (std::size_t k = 0; k < s.amplitude.size(); ++k) {
        const double e = s.amplitude[k] * s.amplitude[k];
        all += e;
        if (s.frequency[k] >= fLo && s.frequency[k] <= fHi) in += e;
    }
    return all > 0.0 ? in / all : 0.0;
}

} // namespace kinstab
