// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// m x = b for a small fixed-size m by Gaussian elimination with partial pivoting. In the planar
// solver's Newton steps Eigen's general LU of the 5x5 matrix took 13 % of the run (perf); this
// plain loop took 9 % of its instructions (callgrind). The elimination is kept, so that further
// right-hand sides reuse it (the later Newton iterations of a Radau step: the elimination was
// two thirds of each solve).

#include <Eigen/Core>

#include <array>
#include <cmath>
#include <utility>

namespace kinstab {

template <int N> class SmallLu {
public:
    using Rows = std::array<std::array<double, N>, N>; // m[i][j]: row i
    // False when a pivot is zero or not finite (m singular to working precision).
    bool factor(const Rows& a) {
        // Rows kept contiguous and the loops unrolled: the strided, looped elimination of
        // Eigen's column-major matrix had been half of the Newton matrices' cost.
        Rows& m = u_; // eliminated in place
        m = a;
#pragma GCC unroll 8
        for (int k = 0; k < N; ++k) {
            int p = k;
            for (int i = k + 1; i < N; ++i)
                if (std::abs(m[i][k]) > std::abs(m[p][k])) p = i;
            if (!(std::abs(m[p][k]) > 0.0) || !std::isfinite(m[p][k])) return false;
            pivot_[k] = p;
            if (p != k) std::swap(m[p], m[k]);
            const double inv = 1.0 / m[k][k];
#pragma GCC unroll 8
            for (int i = k + 1; i < N; ++i) {
                // Kept by step and row position at that step: the solve replays the elimination.
                const double f = multiplier_[k][i] = m[i][k] * inv;
#pragma GCC unroll 8
                for (int j = k + 1; j < N; ++j)
                    m[i][j] -= f * m[k][j];
            }
        }
        return true;
    }
    // b becomes x; only after factor() returned true.
    void solve(Eigen::Matrix<double, N, 1>& b) const {
#pragma GCC unroll 8
        for (int k = 0; k < N; ++k) {
            if (pivot_[k] != k) std::swap(b[pivot_[k]], b[k]);
#pragma GCC unroll 8
            for (int i = k + 1; i < N; ++i)
                b[i] -= multiplier_[k][i] * b[k];
        }
#pragma GCC unroll 8
        for (int k = N - 1; k >= 0; --k) {
            double s = b[k];
#pragma GCC unroll 8
            for (int j = k + 1; j < N; ++j)
                s -= u_[k][j] * b[j];
            b[k] = s / u_[k][k];
        }
    }

private:
    // Set by factor() before any use (not zeroed: that had cost a tenth of the solves).
    Rows u_; // upper triangle: U
    Rows multiplier_;
    std::array<int, N> pivot_;
};

} // namespace kinstab
