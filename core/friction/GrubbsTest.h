// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Grubbs' test for one outlier in a normal sample, used here to challenge a per-run V_inf
// (Furgerson 1980, ch. III and Appendix 2, which is not in the surviving text: the paper only
// says run #7 of BJ-F-NG-200 "does not belong to the same population" at 95 % confidence).
//
// Statistic G = max |x_i - mean| / s (s with the n-1 divisor). Critical value
// (Grubbs 1969, Technometrics 11(1) 1-21; NIST/SEMATECH e-Handbook of Statistical Methods
// section 1.3.5.17):
//   G_crit = (n-1)/sqrt(n) * sqrt(t^2 / (n-2+t^2)),  t = t-quantile at 1 - a with n-2 DOF,
// a = alpha/n for a one-sided test of the largest (or smallest) value, alpha/(2n) two-sided.
// For n = 7, alpha = 0.05: 1.938 one-sided, 2.020 two-sided (ASTM E178 Table 1).

#include <vector>

namespace kinstab {

enum class OutlierSide { Largest, Smallest, TwoSided };

struct GrubbsResult {
    int n = 0;
    int index = -1; // the suspect value (position in the input)
    double value = 0.0;
    double mean = 0.0;
    double sd = 0.0;
    double statistic = 0.0; // G
    double critical = 0.0;  // G_crit at the given alpha
    double alpha = 0.05;
    OutlierSide side = OutlierSide::TwoSided;
    bool rejected = false; // G > G_crit: the suspect is an outlier at confidence 1 - alpha
};

double grubbsCritical(int n, double alpha, OutlierSide side);

// Needs n >= 3 values that are not all equal and 0 < alpha < 1; throws std::invalid_argument.
GrubbsResult grubbsTest(const std::vector<double>& values, double alpha = 0.05,
                        OutlierSide side = OutlierSide::TwoSided);

const char* outlierSideName(OutlierSide side);

} // namespace kinstab
