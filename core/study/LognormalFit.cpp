// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/study/LognormalFit.h"

#include "core/numerics/BrentMinimize.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace kinstab {

namespace {

// ln(1 - Phi(z)), accurate far into the upper tail where erfc underflows.
double logSurvival(double z) {
    const double q = 0.5 * std::erfc(z / std::numbers::sqrt2);
    if (q > 1e-300) return std::log(q);
    // Mills ratio: 1 - Phi(z) ~ phi(z) / z for large z.
    return -0.5 * z * z - std::log(z * std::sqrt(2.0 * std::numbers::pi));
}

// Search box in (ln median, beta): ten log-units beyond the data (a factor of 22,000) and a
// dispersion from 1e-4 to 5 (fitted values of record suites lie between 0.2 and 1).
constexpr double kLogMargin = 10.0;
constexpr double kMinBeta = kMinFragilityBeta, kMaxBeta = kMaxFragilityBeta;
constexpr double kTolerance = 1e-12;

} // namespace

namespace {

// The sample's logarithms, taken once per fit rather than once per likelihood evaluation (a fit
// evaluates it hundreds of times); the sums are the same bits as from the sample itself.
struct LogSample {
    std::vector<double> collapsed, censored;
};

LogSample logsOf(const CensoredSample& s) {
    LogSample l;
    l.collapsed.reserve(s.collapsed.size());
    l.censored.reserve(s.censored.size());
    for (double x : s.collapsed)
        l.collapsed.push_back(std::log(x));
    for (double c : s.censored)
        l.censored.push_back(std::log(c));
    return l;
}

double logLikelihood(const LogSample& s, double m, double beta) {
    const double logNorm = std::log(beta * std::sqrt(2.0 * std::numbers::pi));
    double ll = 0.0;
    for (double lx : s.collapsed) {
        const double z = (lx - m) / beta;
        ll += -0.5 * z * z - logNorm - lx;
    }
    for (double lc : s.censored)
        ll += logSurvival((lc - m) / beta);
    return ll;
}

} // namespace

double lognormalLogLikelihood(const CensoredSample& s, double m, double beta) {
    return logLikelihood(logsOf(s), m, beta);
}

double lognormalCdf(double x, double median, double beta) {
    if (!(x > 0.0)) return 0.0;
    return 0.5 * std::erfc(-std::log(x / median) / (beta * std::numbers::sqrt2));
}

std::optional<LognormalFit> fitLognormal(const CensoredSample& s, std::string* why) {
    auto fail = [why](const char* reason) {
        if (why) *why = reason;
        return std::nullopt;
    };
    std::vector<double> all = s.collapsed;
    all.insert(all.end(), s.censored.begin(), s.censored.end());
    for (double x : all)
        if (!(x > 0.0) || !std::isfinite(x)) return fail("an intensity is not finite and > 0");
    const auto [lo, hi] = std::minmax_element(s.collapsed.begin(), s.collapsed.end());
    if (s.collapsed.size() < 2 || *lo == *hi)
        return fail("fewer than two distinct collapse intensities");
    const auto [allLo, allHi] = std::minmax_element(all.begin(), all.end());
    const double mLo = std::log(*allLo) - kLogMargin, mHi = std::log(*allHi) + kLogMargin;
    // For fixed beta the censored normal log-likelihood is concave in m, so a 1-D minimization
    // finds the best m; the profile over beta is then unimodal (the log-likelihood is concave
    // in (m / beta, 1 / beta)).
    const LogSample logs = logsOf(s);
    auto bestM = [&](double beta) {
        return brentMinimize([&](double m) { return -logLikelihood(logs, m, beta); }, mLo, mHi,
                             kTolerance);
    };
    const MinimumResult b =
        brentMinimize([&](double beta) { return bestM(beta).fx; }, kMinBeta, kMaxBeta, kTolerance);
    const MinimumResult m = bestM(b.x);
    if (!b.converged || !m.converged) return fail("the likelihood maximization did not converge");
    return LognormalFit{std::exp(m.x), b.x, -m.fx};
}

bool betaAtBound(double beta) {
    return beta <= kMinFragilityBeta * (1 + 1e-6) || beta >= kMaxFragilityBeta * (1 - 1e-6);
}

} // namespace kinstab
