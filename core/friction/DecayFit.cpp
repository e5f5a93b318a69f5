// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/friction/DecayFit.h"

#include "core/friction/DecayRegression.h"
#include "core/friction/WorkIntegral.h"
#include "core/numerics/BrentMinimize.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace kinstab {

DecayFit fitDecay(const TripletCurve& curve, double beta, const DecayFitOptions& o) {
    if (const std::string e = validateCurve(curve); !e.empty()) throw std::invalid_argument(e);
    if (!(o.alpha >= 0.0) || !(beta >= 0.0))
        throw std::invalid_argument("alpha and beta must be >= 0");
    DecayFit fit;
    fit.alpha = o.alpha;
    fit.beta = beta;
    fit.v1 = curve.shear(0);
    fit.xi = workAbscissa(curve.delta, curve.shear, beta);
    fit.vInfUpper = curve.shear.minCoeff() - o.boundGap;
    const double lo = std::min(o.lowerBound, fit.vInfUpper - o.boundGap);
    const double hi = fit.vInfUpper;
    auto fm = [&](double vInf) { return decayMeanSquare(fit.xi, curve.shear, vInf, o.alpha); };

    // f_m(V_inf) can have several local minima (Fig. 17 shows one); a scan brackets the best.
    const int n = std::max(o.scanPoints, 3);
    int best = 0;
    double fBest = fm(lo);
    for (int k = 1; k <= n; ++k) {
        const double f = fm(lo + (hi - lo) * k / n);
        if (f < fBest) best = k, fBest = f;
    }
    double xBest = lo + (hi - lo) * best / n;
    const double a = lo + (hi - lo) * std::max(best - 1, 0) / n;
    const double b = lo + (hi - lo) * std::min(best + 1, n) / n;
    const MinimumResult m = brentMinimize(fm, a, b, 1e-10);
    if (m.fx < fBest) xBest = m.x, fBest = m.fx;

    const DecayLine line = fitDecayLine(fit.xi, curve.shear, xBest, o.alpha);
    if (!line.valid || !std::isfinite(fBest))
        throw std::invalid_argument(curveLabel(curve) +
                                    ": the decay law cannot be fitted (singular regression)");
    fit.vInf = xBest;
    fit.c = line.c;
    fit.b = line.b;
    fit.fm = fBest;
    fit.atUpperBound = hi - xBest < 1e-6;
    fit.fitted = decayModel(fit.xi, fit.v1, fit.vInf, line);
    return fit;
}

DecayFit fitDecayBestBeta(const TripletCurve& curve, const std::vector<double>& betas,
                          const DecayFitOptions& o) {
    if (betas.empty()) throw std::invalid_argument("no beta to try");
    DecayFit best = fitDecay(curve, betas.front(), o);
    for (std::size_t i = 1; i < betas.size(); ++i) {
        DecayFit f = fitDecay(curve, betas[i], o);
        if (f.fm < best.fm) best = std::move(f);
    }
    return best;
}

Eigen::VectorXd evaluateDecay(const DecayFit& fit, const TripletCurve& curve,
                              const Eigen::VectorXd& delta) {
    // xi is integrated on the union of the samples and the requested points, so the polyline's
    // kinks stay grid points and xi at the samples is exactly the fitted one.
    std::vector<double> grid(curve.delta.begin(), curve.delta.end());
    const double first = curve.delta(0), last = curve.delta(curve.delta.size() - 1);
    for (const double d : delta)
        grid.push_back(std::clamp(d, first, last));
    std::sort(grid.begin(), grid.end());
    grid.erase(std::unique(grid.begin(), grid.end()), grid.end());
    Eigen::VectorXd g =
        Eigen::Map<const Eigen::VectorXd>(grid.data(), static_cast<Eigen::Index>(grid.size()));
    Eigen::VectorXd v(g.size());
    Eigen::Index k = 1;
    for (Eigen::Index i = 0; i < g.size(); ++i) {
        while (k < curve.delta.size() - 1 && curve.delta(k) < g(i))
            ++k;
        const double t = (g(i) - curve.delta(k - 1)) / (curve.delta(k) - curve.delta(k - 1));
        v(i) = curve.shear(k - 1) + t * (curve.shear(k) - curve.shear(k - 1));
    }
    const Eigen::VectorXd xiGrid = workAbscissa(g, v, fit.beta);
    Eigen::VectorXd xi(delta.size());
    for (Eigen::Index i = 0; i < delta.size(); ++i) {
        const double d = std::clamp(delta(i), first, last);
        xi(i) = xiGrid(std::lower_bound(grid.begin(), grid.end(), d) - grid.begin());
    }
    return decayModel(xi, fit.v1, fit.vInf, DecayLine{fit.c, fit.b, true});
}

} // namespace kinstab
