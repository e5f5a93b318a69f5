// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A lognormal collapse fragility P(collapse | IM = x) = Phi(ln(x / median) / beta) fitted by
// maximum likelihood to per-record critical intensities, with the records that did not collapse
// up to the search limit treated as right-censored at the limit's intensity: they contribute
// 1 - Phi(ln(c / median) / beta) instead of the density (Baker 2015, "Efficient analytical
// fragility function fitting using dynamic structural analysis", Earthquake Spectra 31(1), with
// the censored term of standard survival analysis).

#include <optional>
#include <string>
#include <vector>

namespace kinstab {

struct CensoredSample {
    std::vector<double> collapsed; // g, critical intensities of the records that collapse
    std::vector<double> censored;  // g, limit intensities of the records that do not
};

struct LognormalFit {
    double median = 0; // g, exp(mean of ln IM)
    double beta = 0;   // dispersion, standard deviation of ln IM
    double logLikelihood = 0;
};

// Log-likelihood of (ln median = m, beta) for the sample.
double lognormalLogLikelihood(const CensoredSample& s, double m, double beta);
// None, with the reason in *why, when there is no finite maximum to find: fewer than two
// distinct collapse intensities, or an intensity that is not finite and positive.
std::optional<LognormalFit> fitLognormal(const CensoredSample& s, std::string* why = nullptr);

double lognormalCdf(double x, double median, double beta); // Phi(ln(x/median)/beta)

// The dispersions the fit searches between: a fit at either end is a bound, not an estimate.
inline constexpr double kMinFragilityBeta = 1e-4, kMaxFragilityBeta = 5.0;
bool betaAtBound(double beta);

} // namespace kinstab
