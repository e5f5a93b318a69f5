// SPDX-License-Identifier: GPL-3.0-or-later
// The integrand of lambda_C per unit of ln x that the Study tab plots (core/risk/RiskIntegrand.h)
// and the per-set risk that the tab and kinstab-cli risk share (core/risk/SetRisk.h):
//  - on a power-law hazard k0 x^-k every point is k k0 x^-k Phi(ln(x/theta)/beta), computed here
//    from the formula (|d lambda / d ln x| = k lambda for a power law);
//  - its area over ln x (Simpson's rule on each segment, the test's own quadrature), plus the
//    rate beyond the last point, is lambda_C of the closed-form rule (RiskIntegral) to 1e-6 on a
//    tabulated second-order curve, where the slope changes from segment to segment;
//  - the points are the curve's own at the segment ends, and the density steps there;
//  - a set's risk is analyzeRisk of its fitted fragility, its margin target / lambda_C.

#include "core/risk/RiskIntegrand.h"
#include "core/risk/SetRisk.h"

#include <QtTest>

#include <cmath>
#include <numbers>

using namespace kinstab;

namespace {

double phi(double z) { // the test's own normal CDF
    return 0.5 * std::erfc(-z / std::numbers::sqrt2);
}

HazardCurve tabulate(double (*lambda)(double), double lo, double hi, int n) {
    std::vector<HazardPoint> p;
    for (int i = 0; i < n; ++i) {
        const double x = std::exp(std::log(lo) + (std::log(hi) - std::log(lo)) * i / (n - 1));
        p.push_back({x, lambda(x)});
    }
    return hazardCurve({HazardMeasure::Kind::Pga, 0}, p, "test",
                       [](std::size_t i) { return "point " + std::to_string(i); });
}

double powerLaw(double x) {
    return 1e-4 * std::pow(x, -2.5); // k0 = 1e-4 per year at 1 g, k = 2.5
}

// resources/examples/hazard-second-order.csv's form: k0 = 2e-4, k1 = 2.2, k2 = 0.2.
double secondOrder(double x) {
    const double s = std::log(x);
    return 2e-4 * std::exp(-0.2 * s * s - 2.2 * s);
}

} // namespace

class TestRiskIntegrand : public QObject {
    Q_OBJECT
private slots:
    void powerLawPointsFollowTheFormula() {
        const HazardCurve c = tabulate(powerLaw, 0.01, 5.0, 9);
        const CollapseFragility f{0.8, 0.45};
        const auto pts = riskIntegrand(c, f, 10);
        QCOMPARE(pts.size(), std::size_t(8 * 11));
        for (const RiskIntegrandPoint& p : pts) {
            const double want = 2.5 * powerLaw(p.imG) * phi(std::log(p.imG / 0.8) / 0.45);
            QCOMPARE_LE(std::abs(p.density - want), 1e-12 * want + 1e-300);
            QCOMPARE_LE(std::abs(p.annualRate - powerLaw(p.imG)), 1e-12 * powerLaw(p.imG));
        }
    }
    void segmentEndsAreTheCurvesPoints() {
        const HazardCurve c = tabulate(secondOrder, 0.01, 5.0, 6);
        const auto pts = riskIntegrand(c, {0.5, 0.4}, 4);
        for (std::size_t i = 0; i + 1 < c.points.size(); ++i) {
            QCOMPARE(pts[i * 5].imG, c.points[i].imG);
            QCOMPARE(pts[i * 5 + 4].imG, c.points[i + 1].imG);
        }
        // At an inner point the two segments' slopes differ (the curve bends in log-log): the
        // density steps there while the rate is continuous.
        QCOMPARE_LE(std::abs(pts[4].annualRate - pts[5].annualRate), 1e-12 * pts[4].annualRate);
        QVERIFY(pts[4].density != pts[5].density);
    }
    void areaPlusBeyondIsLambdaC() {
        const HazardCurve c = tabulate(secondOrder, 0.01, 5.0, 25);
        const CollapseFragility f{0.6, 0.5};
        const std::size_t n = 200; // even: Simpson on each segment
        const auto pts = riskIntegrand(c, f, n);
        double area = 0.0;
        for (std::size_t i = 0; i + 1 < c.points.size(); ++i) {
            const double h = std::log(c.points[i + 1].imG / c.points[i].imG) / n;
            double sum = 0.0;
            for (std::size_t j = 0; j <= n; ++j) {
                const double w = j == 0 || j == n ? 1.0 : (j % 2 ? 4.0 : 2.0);
                sum += w * pts[i * (n + 1) + j].density;
            }
            area += sum * h / 3.0;
        }
        const RiskIntegral r = riskIntegral(c, f);
        QCOMPARE_LE(std::abs(area - r.withinCurve), 1e-6 * r.withinCurve);
        QCOMPARE_LE(std::abs(area + r.beyondLastPoint - r.lambdaC), 1e-6 * r.lambdaC);
    }
    void setRiskIsTheFitsRisk() {
        // Five records collapsing at 0.3 .. 0.7 g (no censoring): the fit is their log mean and
        // (divisor n) log standard deviation (docs/studies.md, "Fragility").
        std::vector<StudyRow> rows;
        for (int i = 0; i < 5; ++i) {
            StudyRow r;
            r.index = static_cast<std::size_t>(i);
            r.cases = 5;
            r.record = "r" + std::to_string(i);
            r.mu = 0.6;
            r.tstar = 0.099;
            r.limit = 1;
            r.measure = "pga";
            r.recordIntensity = 0.2;
            r.criticalIntensity = 0.3 + 0.1 * i;
            r.criticalPeak = r.criticalIntensity;
            r.limitIntensity = 3.0;
            rows.push_back(r);
        }
        const HazardCurve c = tabulate(secondOrder, 0.01, 5.0, 25);
        RiskSettings s;
        BootstrapSettings b;
        b.resamples = 50;
        const SetRisk x = setRisk(c, rows, s, b);
        QVERIFY(x.risk && x.bootstrap);
        const RiskResult want = analyzeRisk(c, {x.fragility.fit->median, x.fragility.fit->beta}, s);
        QCOMPARE(x.risk->integral.lambdaC, want.integral.lambdaC);
        QCOMPARE(*x.margin, s.targetRate / want.integral.lambdaC);
        QCOMPARE(x.bootstrap->resamples, std::size_t(50));
        QCOMPARE(x.integrand.size(), (c.points.size() - 1) * (kIntegrandPointsPerSegment + 1));
        const std::vector<SetRisk> all = studySetRisks(c, rows, s, b);
        QCOMPARE(all.size(), std::size_t(1));
        QCOMPARE(all[0].risk->integral.lambdaC, x.risk->integral.lambdaC);
    }
};

QTEST_MAIN(TestRiskIntegrand)
#include "tst_risk_integrand.moc"
