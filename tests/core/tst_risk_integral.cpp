// SPDX-License-Identifier: GPL-3.0-or-later
// The risk integral lambda_C = integral of P(C|x) |d lambda(x)| (core/risk/RiskIntegral.h) and
// what is computed beside it, against exact references:
//  - a power-law hazard k0 x^-k is linear in log-log, so the rule is exact on it at any spacing:
//    lambda_C = k0 theta^-k exp(k^2 beta^2 / 2) (Cornell et al. 2002, SPEC section 14), to
//    rounding, for 5 points as for 2000;
//  - a second-order hazard k0 exp(-k2 ln^2 x - k1 ln x) is not: the tabulated integral converges
//    to its closed form (Vamvatsikos 2013) as h^2 in the spacing h (each doubling of the points
//    divides the error by 4), the closed form itself checked against a direct quadrature;
//  - each segment's closed-form integral against a brute-force Simpson sum of P(C|x) |d lambda|
//    on the same log-log curve, also where a steep segment and a wide beta would overflow a
//    naive formula, and for a near-step fragility;
//  - a 3-point curve computed by hand (an independent calculation, not a published example);
//  - the risk-targeted median against the power law's closed form, Phi^-1(0.1), 1 % in 50 years;
//  - the closed-form fits of a tabulated curve recover the exact forms;
//  - the bootstrap percentiles and the tails of the normal distribution.

#include "core/numerics/NormalTail.h"
#include "core/risk/RiskAnalysis.h"

#include <QtTest>

#include <cmath>
#include <functional>
#include <numbers>
#include <vector>

using namespace kinstab;

namespace {

double relative(double got, double want) {
    return std::abs(got - want) / std::abs(want);
}

// n points of lambda at intensities evenly spaced in ln x over [lo, hi] g.
HazardCurve tabulate(const std::function<double(double)>& lambda, double lo, double hi, int n) {
    std::vector<HazardPoint> p;
    for (int i = 0; i < n; ++i) {
        const double x = std::exp(std::log(lo) + (std::log(hi) - std::log(lo)) * i / (n - 1));
        p.push_back({x, lambda(x)});
    }
    return hazardCurve({HazardMeasure::Kind::Pga, 0}, p, "test",
                       [](std::size_t i) { return "point " + std::to_string(i); });
}

double phi(double z) { // the test's own normal CDF
    return 0.5 * std::erfc(-z / std::numbers::sqrt2);
}

struct SecondOrder {
    double k0, k1, k2;
    double operator()(double x) const {
        const double s = std::log(x);
        return k0 * std::exp(-k2 * s * s - k1 * s);
    }
};

// The Gaussian integral of a second-order hazard against the lognormal density, derived in the
// test: completing the square in s = ln x gives sqrt(q) k0^(1-q) lambda(theta)^q
// exp(q k1^2 beta^2 / 2), q = 1 / (1 + 2 k2 beta^2).
double secondOrderExact(const SecondOrder& h, double theta, double beta) {
    const double q = 1.0 / (1.0 + 2.0 * h.k2 * beta * beta);
    return std::sqrt(q) * std::pow(h.k0, 1.0 - q) * std::pow(h(theta), q) *
           std::exp(q * h.k1 * h.k1 * beta * beta / 2.0);
}

// Composite Simpson over [a, b] with n (even) intervals.
double simpson(const std::function<double(double)>& f, double a, double b, int n) {
    const double h = (b - a) / n;
    double sum = f(a) + f(b);
    for (int i = 1; i < n; ++i)
        sum += f(a + i * h) * (i % 2 ? 4.0 : 2.0);
    return sum * h / 3.0;
}

// The rule by brute force: on each segment P(C|x) |d lambda| = P k lambda(s) ds with the
// segment's power law, Simpson's rule on n intervals, plus lambda(x_max) P(x_max).
double bruteForce(const HazardCurve& c, const CollapseFragility& f, int n) {
    const auto& p = c.points;
    double sum = p.back().annualRate * collapseProbability(f, p.back().imG);
    for (std::size_t i = 0; i + 1 < p.size(); ++i) {
        const double sa = std::log(p[i].imG), sb = std::log(p[i + 1].imG);
        const double k = std::log(p[i].annualRate / p[i + 1].annualRate) / (sb - sa);
        sum += simpson(
            [&](double s) {
                return phi((s - std::log(f.medianG)) / f.beta) * k * p[i].annualRate *
                       std::exp(-k * (s - sa));
            },
            sa, sb, n);
    }
    return sum;
}

} // namespace

class TestRiskIntegral : public QObject {
    Q_OBJECT
private slots:
    void powerLawIsExact_data() {
        QTest::addColumn<double>("k0");
        QTest::addColumn<double>("k");
        QTest::addColumn<double>("theta");
        QTest::addColumn<double>("beta");
        QTest::addColumn<int>("points");
        QTest::newRow("k=3 theta=0.5 beta=0.4, 5 points") << 1e-4 << 3.0 << 0.5 << 0.4 << 5;
        QTest::newRow("k=3 theta=0.5 beta=0.4, 2000 points") << 1e-4 << 3.0 << 0.5 << 0.4 << 2000;
        QTest::newRow("k=2.5 theta=1.2 beta=0.6, 40 points") << 2e-4 << 2.5 << 1.2 << 0.6 << 40;
        QTest::newRow("k=1.5 theta=0.3 beta=0.3, 12 points") << 1e-3 << 1.5 << 0.3 << 0.3 << 12;
    }
    void powerLawIsExact() {
        QFETCH(double, k0);
        QFETCH(double, k);
        QFETCH(double, theta);
        QFETCH(double, beta);
        QFETCH(int, points);
        // From below the integrand's peak (ln theta - k beta^2) by 10 beta to 10 beta above the
        // median: what lies beyond is below Phi(-10) = 7.6e-24 of the result.
        const double lo = theta * std::exp(-k * beta * beta - 10 * beta);
        const double hi = theta * std::exp(10 * beta);
        const HazardCurve c =
            tabulate([&](double x) { return k0 * std::pow(x, -k); }, lo, hi, points);
        const CollapseFragility f{theta, beta};
        const double want = k0 * std::pow(theta, -k) * std::exp(k * k * beta * beta / 2); // Cornell
        const double got = riskIntegral(c, f).lambdaC;
        QCOMPARE_LE(relative(got, want), 1e-12);
        QCOMPARE_LE(relative(firstOrderRiskRate(k0, k, f), want), 1e-14);
        const FirstOrderForm first = firstOrderForm(c, f); // the local power law is the curve
        QVERIFY2(first.why.empty(), first.why.c_str());
        QCOMPARE_LE(relative(first.k, k), 1e-12);
        QCOMPARE_LE(relative(first.lambdaC, want), 1e-12);
    }

    void secondOrderConvergesAsHSquared() {
        // k0 = 2e-4, k1 = 2.2, k2 = 0.2 (resources/examples/hazard-second-order.csv), theta = 1 g,
        // beta = 0.5, over ln x in [-5, 3]: inside the curve's decreasing part (its top is at
        // ln x = -k1 / (2 k2) = -5.5) and 10 beta below and 6 beta above the median.
        const SecondOrder h{2e-4, 2.2, 0.2};
        const CollapseFragility f{1.0, 0.5};
        const double exact = secondOrderExact(h, f.medianG, f.beta);
        // The closed form against a direct quadrature of lambda(s) N(s; 0, beta^2) (the integral
        // by parts), Simpson on 40000 intervals over s in [-8, 8].
        const double direct = simpson(
            [&](double s) {
                return h(std::exp(s)) * std::exp(-s * s / (2 * f.beta * f.beta)) /
                       (f.beta * std::sqrt(2 * std::numbers::pi));
            },
            -8, 8, 40000);
        QCOMPARE_LE(relative(direct, exact), 1e-12);
        const std::optional<double> form = secondOrderRiskRate(h.k0, h.k1, h.k2, f);
        QVERIFY(form);
        QCOMPARE_LE(relative(*form, exact), 1e-13);
        double previous = 0;
        for (int n : {26, 51, 101, 201, 401, 801, 1601}) { // spacing h halves each time
            const double err = relative(
                riskIntegral(tabulate(h, std::exp(-5.0), std::exp(3.0), n), f).lambdaC, exact);
            qInfo("%5d points: relative error %.3e", n, err);
            if (previous > 0) { // O(h^2): a ratio of 4 per halving
                QCOMPARE_GE(previous / err, 3.9);
                QCOMPARE_LE(previous / err, 4.1);
            }
            previous = err;
        }
        QCOMPARE_LE(previous, 2e-6); // 1601 points
    }

    void segmentsAgainstBruteForce_data() {
        QTest::addColumn<QVector<double>>("im");
        QTest::addColumn<QVector<double>>("rate");
        QTest::addColumn<double>("theta");
        QTest::addColumn<double>("beta");
        QTest::newRow("3 points, median inside")
            << QVector<double>{0.1, 0.3, 1.0} << QVector<double>{1e-2, 1e-3, 5e-5} << 0.4 << 0.5;
        QTest::newRow("flat segment")
            << QVector<double>{0.1, 0.3, 1.0} << QVector<double>{1e-3, 1e-3, 1e-4} << 0.2 << 0.4;
        // k = ln(1e6) / ln(1.2) = 75.8, beta = 5: exp(k^2 beta^2 / 2) overflows a naive formula.
        QTest::newRow("steep segment, beta 5")
            << QVector<double>{0.5, 1.0, 1.2} << QVector<double>{1e-3, 1e-4, 1e-10} << 0.3 << 5.0;
        QTest::newRow("steep segment above the median, beta 0.6")
            << QVector<double>{0.5, 1.0, 1.2} << QVector<double>{1e-3, 1e-4, 1e-10} << 0.05 << 0.6;
        QTest::newRow("median far above the curve")
            << QVector<double>{0.1, 0.3, 1.0} << QVector<double>{1e-2, 1e-3, 5e-5} << 50.0 << 0.3;
        QTest::newRow("near-step fragility, beta 0.001")
            << QVector<double>{0.1, 0.3, 1.0} << QVector<double>{1e-2, 1e-3, 5e-5} << 0.5 << 1e-3;
    }
    void segmentsAgainstBruteForce() {
        QFETCH(QVector<double>, im);
        QFETCH(QVector<double>, rate);
        QFETCH(double, theta);
        QFETCH(double, beta);
        std::vector<HazardPoint> p;
        for (qsizetype i = 0; i < im.size(); ++i)
            p.push_back({im[i], rate[i]});
        const HazardCurve c = hazardCurve({}, p, "test", [](std::size_t) { return ""; });
        const CollapseFragility f{theta, beta};
        const double got = riskIntegral(c, f).lambdaC;
        const double want = bruteForce(c, f, 200000);
        QVERIFY(std::isfinite(got));
        QCOMPARE_LE(std::abs(got - want), 1e-10 * want + 1e-300);
    }

    void threePointsByHand() {
        // An independent calculation by hand (no published source): points (0.2 g, 1e-2),
        // (0.4 g, 1e-3), (0.8 g, 1e-4), theta = 0.4 g, beta = 0.3. Both segments are the power law
        // 1e-3 (x/0.4)^-k, k = ln 10 / ln 2 = 3.321928. On a power-law segment the integral of
        // lambda against the fragility's density is lambda(theta) exp(k^2 beta^2 / 2)
        // [Phi(zb) - Phi(za)], z = (ln(x / theta) + k beta^2) / beta:
        //   k^2 beta^2 / 2 = 0.496584, exp = 1.643099; za = ln(0.5)/0.3 + 0.996578 = -1.313912,
        //   zb = 2.310491 + 0.996578 = 3.307069; Phi(zb) - Phi(za) = 0.999529 - 0.094438
        //   = 0.905091 (normal table), so G = 1e-3 x 1.643099 x 0.905091 = 1.487154e-3.
        //   P(C|0.2) = Phi(-2.310491) = 0.010431, P(C|0.8) = Phi(2.310491) = 0.989569.
        // Within the curve, integral of P |d lambda| = lambda0 P0 - lambda2 P2 + G
        //   = 1.0431e-4 - 0.98957e-4 + 1.487154e-3 = 1.492502e-3; beyond the last point
        //   lambda2 P2 = 0.98957e-4; lambda_C = 1.591459e-3. (The untruncated power law gives
        //   1e-3 x 1.643099 = 1.643099e-3: the curve's ends take 3.1 % off.)
        const std::vector<HazardPoint> p = {{0.2, 1e-2}, {0.4, 1e-3}, {0.8, 1e-4}};
        const HazardCurve c = hazardCurve({}, p, "hand", [](std::size_t) { return ""; });
        const RiskIntegral r = riskIntegral(c, {0.4, 0.3});
        QCOMPARE_LE(relative(r.lambdaC, 1.591459e-3), 2e-6);
        QCOMPARE_LE(relative(r.withinCurve, 1.492502e-3), 2e-6);
        QCOMPARE_LE(relative(r.beyondLastPoint, 0.98957e-4), 1e-5);
        QCOMPARE_LE(relative(r.pAtFirstPoint, 0.010431), 1e-4);
        QCOMPARE_LE(relative(r.pAtLastPoint, 0.989569), 1e-6);
    }

    void riskTargetedMedianOfAPowerLaw_data() {
        QTest::addColumn<double>("k0");
        QTest::addColumn<double>("k");
        QTest::addColumn<double>("beta");
        QTest::addColumn<double>("target");
        QTest::newRow("ASCE 7-22 target, beta 0.6") << 1e-4 << 3.0 << 0.6 << codeTargetRate();
        QTest::newRow("1e-5, beta 0.4") << 2e-4 << 2.0 << 0.4 << 1e-5;
    }
    void riskTargetedMedianOfAPowerLaw() {
        QFETCH(double, k0);
        QFETCH(double, k);
        QFETCH(double, beta);
        QFETCH(double, target);
        // k0 theta^-k exp(k^2 beta^2 / 2) = target: theta = (k0 exp(k^2 beta^2 / 2) /
        // target)^(1/k).
        const double want = std::pow(k0 * std::exp(k * k * beta * beta / 2) / target, 1.0 / k);
        const double lo = want * std::exp(-k * beta * beta - 12 * beta);
        const double hi = want * std::exp(10 * beta); // within 1000 g
        const HazardCurve c = tabulate([&](double x) { return k0 * std::pow(x, -k); }, lo, hi, 30);
        const RiskTargetedMedian t = riskTargetedMedian(c, beta, target);
        QVERIFY2(t.medianG, t.why.c_str());
        QCOMPARE_LE(relative(*t.medianG, want), 1e-10);
        QCOMPARE_LE(t.iterations, 200);
        // A target at or above the curve's largest rate: every median meets it.
        QVERIFY(!riskTargetedMedian(c, beta, 2 * c.points.front().annualRate).medianG);
    }

    void codeTargets() {
        // 1 % in 50 years (ASCE 7-22 ch. 21): -ln(0.99) / 50 = 2.0100671707e-4 per year, and its
        // probability in 50 years is 1 % back.
        QCOMPARE_LE(relative(codeTargetRate(), 2.0100671707e-4), 1e-10);
        QCOMPARE_LE(relative(probabilityInYears(codeTargetRate(), 50), 0.01), 1e-13);
        // Phi(-1.2815515655446004) = 0.1 (the test's own erfc).
        QCOMPARE_LE(std::abs(phi(kNormalQuantile10) - 0.1), 1e-16);
        // theta = x10 exp(1.2816 beta) (SPEC section 14): theta 1 g, beta 0.6, x10 =
        // exp(-0.768931).
        QCOMPARE_LE(relative(imAtTenPercent({1.0, 0.6}), std::exp(-0.6 * 1.2815515655446004)),
                    1e-15);
        QCOMPARE_LE(std::abs(collapseProbability({1.0, 0.6}, imAtTenPercent({1.0, 0.6})) - 0.1),
                    1e-15);
    }

    void closedFormFitsRecoverTheExactForms() {
        // On the second-order hazard the symmetric secant of ln lambda through theta e^-beta and
        // theta e^beta is the tangent at theta: k = 2 k2 ln(theta) + k1; the curve's points lie
        // on the quadratic, so the least-squares fit is exact. theta = 0.6 g, beta = 0.45, 801
        // points over [e^-5, e^3] (the interpolated lambda(theta) is within 1e-5 of exact).
        const SecondOrder h{2e-4, 2.2, 0.2};
        const CollapseFragility f{0.6, 0.45};
        const HazardCurve c = tabulate(h, std::exp(-5.0), std::exp(3.0), 801);
        const FirstOrderForm first = firstOrderForm(c, f);
        QVERIFY(first.why.empty());
        // The interpolation between points 0.01 apart in ln x is within k2 h^2 / 4 = 5e-6 of
        // ln lambda, so the secant over 2 beta = 0.9 within 1.2e-5 of the tangent.
        QCOMPARE_LE(std::abs(first.k - (2 * 0.2 * std::log(0.6) + 2.2)), 1.2e-5);
        const SecondOrderForm second = secondOrderForm(c, f);
        QVERIFY2(second.why.empty(), second.why.c_str());
        QCOMPARE_LE(relative(second.k0, 2e-4), 1e-9);
        QCOMPARE_LE(std::abs(second.k1 - 2.2), 1e-9);
        QCOMPARE_LE(std::abs(second.k2 - 0.2), 1e-9);
        QCOMPARE_LE(relative(second.lambdaC, secondOrderExact(h, 0.6, 0.45)), 1e-9);
        QVERIFY(second.points >= 3);
        // A median outside the curve: no local fit.
        QVERIFY(!firstOrderForm(c, {100.0, 0.4}).why.empty());
        QVERIFY(!secondOrderForm(c, {100.0, 0.4}).why.empty());
    }

    void closedFormsSayWhyTheyOverflow() {
        // A steep top (1e-4 to 1e-10 between 1 and 1.2 g) and beta 5: the secant's k = 18.4 and
        // exp(k^2 beta^2 / 2) = exp(4232) is beyond double precision; the integral is finite.
        const std::vector<HazardPoint> p = {{0.5, 1e-3}, {1.0, 1e-4}, {1.2, 1e-10}};
        const HazardCurve c = hazardCurve({}, p, "steep", [](std::size_t) { return ""; });
        const CollapseFragility f{1.0, 5.0};
        QVERIFY(std::isfinite(riskIntegral(c, f).lambdaC));
        const FirstOrderForm first = firstOrderForm(c, f);
        QVERIFY2(first.why.find("overflows") != std::string::npos, first.why.c_str());
        const SecondOrderForm second = secondOrderForm(c, f);
        QVERIFY(!second.why.empty() || std::isfinite(second.lambdaC));
    }

    void bootstrapPercentiles() {
        // lambda_C of five resamples on a power law (each k0 theta^-k exp(k^2 beta^2 / 2) by the
        // first test; the curve 1e-3 to 500 g reaches 10 beta beyond each) and one unfitted
        // resample counted as 0: sorted {0, l(2.0), l(1.5), l(1.0), l(0.8), l(0.6)}; type-7
        // quantiles at positions 0.25, 2.5 and 4.75 of 0..5.
        const double k0 = 1e-4, k = 3, beta = 0.4;
        const auto l = [&](double theta) {
            return k0 * std::pow(theta, -k) * std::exp(k * k * beta * beta / 2);
        };
        const HazardCurve c =
            tabulate([&](double x) { return k0 * std::pow(x, -k); }, 1e-3, 500, 60);
        std::vector<std::optional<LognormalFit>> fits;
        for (double theta : {1.0, 0.6, 2.0, 1.5, 0.8})
            fits.push_back(LognormalFit{theta, beta, 0.0});
        fits.push_back(std::nullopt);
        const RiskBootstrap b = riskBootstrap(c, fits, 50);
        QCOMPARE(b.resamples, std::size_t(6));
        QCOMPARE(b.fitted, std::size_t(5));
        QCOMPARE_LE(relative(b.lambdaC.p5, 0.25 * l(2.0)), 1e-11);
        QCOMPARE_LE(relative(b.lambdaC.p50, l(1.5) + 0.5 * (l(1.0) - l(1.5))), 1e-11);
        QCOMPARE_LE(relative(b.lambdaC.p95, l(0.8) + 0.75 * (l(0.6) - l(0.8))), 1e-11);
        QCOMPARE_LE(
            relative(b.pInYears.p50, 0.5 * (-std::expm1(-50 * l(1.5)) - std::expm1(-50 * l(1.0)))),
            1e-11);
    }

    void normalTails() {
        // erfcx against exp(x^2) erfc(x) where the product is still representable.
        for (double x : {3.0, 4.5, 7.0, 12.0, 20.0, 26.0})
            QCOMPARE_LE(relative(erfcx(x), std::exp(x * x) * std::erfc(x)), 5e-13);
        // Far out, ln Q(z) = -z^2/2 - ln(z sqrt(2 pi)) + ln(1 - 1/z^2 + 3/z^4 - ...), the
        // asymptotic series of the Mills ratio (integration by parts of the tail integral).
        for (double z : {40.0, 100.0, 1e4}) {
            const double series =
                std::log(1 - 1 / (z * z) + 3 / std::pow(z, 4) - 15 / std::pow(z, 6));
            QCOMPARE_LE(
                std::abs(logNormalTail(z) -
                         (-z * z / 2 - std::log(z * std::sqrt(2 * std::numbers::pi)) + series)),
                1e-12 * z * z);
        }
        // Q(5) = 2.866515718791946e-07 (Python's 0.5 * math.erfc(5 / math.sqrt(2))).
        QCOMPARE_LE(relative(normalTail(5.0), 2.866515718791946e-7), 1e-14);
    }
};

QTEST_GUILESS_MAIN(TestRiskIntegral)
#include "tst_risk_integral.moc"
