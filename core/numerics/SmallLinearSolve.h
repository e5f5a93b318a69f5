// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// m x = b for a small fixed-size m by Gaussian elimination with partial pivoting, in place (b
// becomes x). In the planar solver's Newton steps Eigen's general LU of the 5x5 matrix took 13 %
// of the run (perf); this plain loop takes 9 % of its instructions (callgrind).

#include <Eigen/Core>

#include <cmath>
#include <utility>

namespace kinstab {

// Returns false when a pivot is zero or not finite (m singular to working precision).
template <int N> bool solveInPlace(Eigen::Matrix<double, N, N>& m, Eigen::Matrix<double, N, 1>& b) {
    for (int k = 0; k < N; ++k) {
        int p = k;
        for (int i = k + 1; i < N; ++i)
            if (std::abs(m(i, k)) > std::abs(m(p, k))) p = i;
        if (!(std::abs(m(p, k)) > 0.0) || !std::isfinite(m(p, k))) return false;
        if (p != k) {
            m.row(p).swap(m.row(k));
            std::swap(b[p], b[k]);
        }
        const double inv = 1.0 / m(k, k);
        for (int i = k + 1; i < N; ++i) {
            const double f = m(i, k) * inv;
            for (int j = k + 1; j < N; ++j)
                m(i, j) -= f * m(k, j);
            b[i] -= f * b[k];
        }
    }
    for (int k = N - 1; k >= 0; --k) {
        double s = b[k];
        for (int j = k + 1; j < N; ++j)
            s -= m(k, j) * b[j];
        b[k] = s / m(k, k);
    }
    return true;
}

} // namespace kinstab
