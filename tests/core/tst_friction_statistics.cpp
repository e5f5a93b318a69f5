// SPDX-License-Identifier: GPL-3.0-or-later
// Percentage points, Grubbs' outlier test and the confidence intervals of Furgerson (1980)
// Table 3c.

#include "FurgersonTables.h"

#include "core/friction/ConfidenceIntervals.h"
#include "core/friction/GrubbsTest.h"
#include "core/numerics/ChiSquared.h"
#include "core/numerics/IncompleteBeta.h"
#include "core/numerics/IncompleteGamma.h"
#include "core/numerics/StudentT.h"

#include <QtTest>

#include <cmath>

using namespace kinstab;

namespace {

// The per-run V_inf printed in Table 3a (alpha = 2, beta = 0), runs #30 #7 #43 #34 #36 #21 #11.
std::vector<double> table3aVInf(bool withRun7) {
    std::vector<double> v;
    for (const auto& r : furgerson::rows("table3a_fits.csv"))
        if (r.at("beta") == "0" && (withRun7 || r.at("run") != "7"))
            v.push_back(std::stod(r.at("V_inf")));
    return v;
}

} // namespace

class TestFrictionStatistics : public QObject {
    Q_OBJECT
private slots:
    void incompleteFunctions();
    void studentT_data();
    void studentT();
    void chiSquared_data();
    void chiSquared();
    void grubbsCritical_data();
    void grubbsCritical();
    void run7IsAnOutlier();
    void table3cPrintedPoints_data();
    void table3cPrintedPoints();
    void table3cExactPoints();
    void badInput();
};

void TestFrictionStatistics::incompleteFunctions() {
    // Closed forms: I_x(1, 1) = x; I_x(a, 1) = x^a; P(1, x) = 1 - e^-x; P(1/2, x) = erf(sqrt x).
    QCOMPARE_LE(std::abs(regularizedIncompleteBeta(1, 1, 0.3) - 0.3), 1e-14);
    QCOMPARE_LE(std::abs(regularizedIncompleteBeta(2.5, 1, 0.7) - std::pow(0.7, 2.5)), 1e-13);
    QCOMPARE_LE(std::abs(regularizedLowerGamma(1, 2.0) - (1 - std::exp(-2.0))), 1e-14);
    QCOMPARE_LE(std::abs(regularizedLowerGamma(0.5, 3.0) - std::erf(std::sqrt(3.0))), 1e-13);
    QCOMPARE_LE(std::abs(regularizedLowerGamma(0.5, 30.0) - std::erf(std::sqrt(30.0))), 1e-13);
    QVERIFY(std::isnan(regularizedIncompleteBeta(-1, 1, 0.5)));
    QVERIFY(std::isnan(regularizedLowerGamma(1, -1)));
}

void TestFrictionStatistics::studentT_data() {
    QTest::addColumn<double>("p");
    QTest::addColumn<double>("dof");
    QTest::addColumn<double>("tabulated");
    // Abramowitz & Stegun Table 26.10 (3 decimals); the 5-DOF points are also Table 3c's.
    QTest::newRow("A&S 26.10 p=.975 nu=1") << 0.975 << 1.0 << 12.706;
    QTest::newRow("A&S 26.10 p=.995 nu=1") << 0.995 << 1.0 << 63.657;
    QTest::newRow("Table 3c 10-90 nu=5") << 0.90 << 5.0 << 1.476;
    QTest::newRow("Table 3c 5-95 nu=5") << 0.95 << 5.0 << 2.015;
    QTest::newRow("Table 3c 1-99 nu=5") << 0.99 << 5.0 << 3.365;
    QTest::newRow("A&S 26.10 p=.999 nu=5") << 0.999 << 5.0 << 5.893;
    QTest::newRow("A&S 26.10 p=.975 nu=10") << 0.975 << 10.0 << 2.228;
    QTest::newRow("A&S 26.10 p=.975 nu=30") << 0.975 << 30.0 << 2.042;
    QTest::newRow("A&S 26.10 p=.995 nu=30") << 0.995 << 30.0 << 2.750;
}

void TestFrictionStatistics::studentT() {
    QFETCH(double, p);
    QFETCH(double, dof);
    QFETCH(double, tabulated);
    const double t = studentTQuantile(p, dof);
    QCOMPARE_LE(std::abs(t - tabulated), 0.0005);
    QCOMPARE_LE(std::abs(studentTCdf(t, dof) - p), 1e-12);
    QCOMPARE_LE(std::abs(studentTQuantile(1 - p, dof) + t), 1e-9); // symmetry
}

void TestFrictionStatistics::chiSquared_data() {
    QTest::addColumn<double>("p");
    QTest::addColumn<double>("dof");
    QTest::addColumn<double>("tabulated");
    // Abramowitz & Stegun Table 26.8 (3 decimals). Table 3c prints the 5-DOF points rounded to
    // 3 figures (15.1, .554, 11.1, 1.15, 9.24, 1.61).
    QTest::newRow("A&S 26.8 p=.95 k=1") << 0.95 << 1.0 << 3.841;
    QTest::newRow("A&S 26.8 p=.99 k=1") << 0.99 << 1.0 << 6.635;
    QTest::newRow("A&S 26.8 p=.01 k=5") << 0.01 << 5.0 << 0.554;
    QTest::newRow("A&S 26.8 p=.05 k=5") << 0.05 << 5.0 << 1.145;
    QTest::newRow("A&S 26.8 p=.10 k=5") << 0.10 << 5.0 << 1.610;
    QTest::newRow("A&S 26.8 p=.90 k=5") << 0.90 << 5.0 << 9.236;
    QTest::newRow("A&S 26.8 p=.95 k=5") << 0.95 << 5.0 << 11.070;
    QTest::newRow("A&S 26.8 p=.99 k=5") << 0.99 << 5.0 << 15.086;
    QTest::newRow("A&S 26.8 p=.025 k=10") << 0.025 << 10.0 << 3.247;
    QTest::newRow("A&S 26.8 p=.975 k=10") << 0.975 << 10.0 << 20.483;
    QTest::newRow("A&S 26.8 p=.05 k=30") << 0.05 << 30.0 << 18.493;
    QTest::newRow("A&S 26.8 p=.95 k=30") << 0.95 << 30.0 << 43.773;
}

void TestFrictionStatistics::chiSquared() {
    QFETCH(double, p);
    QFETCH(double, dof);
    QFETCH(double, tabulated);
    const double x = chiSquaredQuantile(p, dof);
    QCOMPARE_LE(std::abs(x - tabulated), 0.0005);
    QCOMPARE_LE(std::abs(chiSquaredCdf(x, dof) - p), 1e-12);
}

void TestFrictionStatistics::grubbsCritical_data() {
    QTest::addColumn<int>("n");
    QTest::addColumn<double>("alpha");
    QTest::addColumn<double>("tabulated");
    // One-sided critical values, Grubbs (1969) Technometrics 11, Table 1 = ASTM E178 Table 1
    // (3 decimals; the old tables round some entries up by 0.001, hence the tolerance).
    const struct {
        int n;
        double a5, a1;
    } table[] = {{3, 1.153, 1.155}, {4, 1.463, 1.492}, {5, 1.672, 1.749}, {6, 1.822, 1.944},
                 {7, 1.938, 2.097}, {8, 2.032, 2.221}, {9, 2.110, 2.323}, {10, 2.176, 2.410}};
    for (const auto& r : table) {
        QTest::addRow("Grubbs 1969 n=%d 5%%", r.n) << r.n << 0.05 << r.a5;
        QTest::addRow("Grubbs 1969 n=%d 1%%", r.n) << r.n << 0.01 << r.a1;
    }
}

void TestFrictionStatistics::grubbsCritical() {
    QFETCH(int, n);
    QFETCH(double, alpha);
    QFETCH(double, tabulated);
    QCOMPARE_LE(std::abs(kinstab::grubbsCritical(n, alpha, OutlierSide::Largest) - tabulated),
                0.001);
}

void TestFrictionStatistics::run7IsAnOutlier() {
    // Furgerson 1980 ch. III: "within 95 % confidence the value of V_inf given in test #7 does
    // not belong to the same population". G from Table 3a's printed V_inf = 2.036.
    const std::vector<double> v = table3aVInf(true);
    QCOMPARE(v.size(), std::size_t(7));
    const GrubbsResult twoSided = grubbsTest(v, 0.05, OutlierSide::TwoSided);
    QCOMPARE(twoSided.index, 1); // run #7 (second column of Table 3a)
    QCOMPARE_LE(std::abs(twoSided.statistic - 2.0355), 5e-4);
    QVERIFY(twoSided.rejected);                                  // G = 2.036 > 2.020
    QVERIFY(grubbsTest(v, 0.05, OutlierSide::Largest).rejected); // > 1.938
    // Not at 99 %: 2.036 < 2.097 (one-sided). The paper claims 95 % only.
    QVERIFY(!grubbsTest(v, 0.01, OutlierSide::Largest).rejected);
    // Without #7, nothing else stands out.
    QVERIFY(!grubbsTest(table3aVInf(false), 0.05).rejected);
}

void TestFrictionStatistics::table3cPrintedPoints_data() {
    QTest::addColumn<double>("tail");
    QTest::addColumn<QString>("row");
    QTest::newRow("Table 3c 1-99") << 0.01 << "1-99";
    QTest::newRow("Table 3c 5-95") << 0.05 << "5-95";
    QTest::newRow("Table 3c 10-90") << 0.10 << "10-90";
}

void TestFrictionStatistics::table3cPrintedPoints() {
    // With the percentage points Table 3c prints, every bound is reproduced to 3 decimals.
    QFETCH(double, tail);
    QFETCH(QString, row);
    for (const auto& r : furgerson::rows("table3c_confidence.csv")) {
        if (r.at("percentile_points") != row.toStdString()) continue;
        const PercentagePoints printed{std::stod(r.at("chi2_upper_point_5dof")),
                                       std::stod(r.at("chi2_lower_point_5dof")),
                                       std::stod(r.at("t_point_5dof"))};
        const SampleIntervals s = sampleIntervals(table3aVInf(false), tail, printed);
        const auto near = [&](double got, const char* column) {
            const double want = std::stod(r.at(column));
            if (std::abs(got - want) > 0.0005)
                qWarning("%s: got %.4f, Table 3c %.3f", column, got, want);
            return std::abs(got - want) <= 0.0005;
        };
        QVERIFY(near(s.mean, "mean_vinf_estimate"));
        QVERIFY(near(s.variance, "var_estimate"));
        QVERIFY(near(s.sd, "sd_estimate"));
        QVERIFY(near(s.varianceLower, "var_lower"));
        QVERIFY(near(s.varianceUpper, "var_upper"));
        QVERIFY(near(s.sdLower, "sd_lower"));
        QVERIFY(near(s.sdUpper, "sd_upper"));
        QVERIFY(near(s.meanLower, "mean_vinf_lower"));
        QVERIFY(near(s.meanUpper, "mean_vinf_upper"));
        return;
    }
    QFAIL("row not found in table3c_confidence.csv");
}

void TestFrictionStatistics::table3cExactPoints() {
    // With exact percentage points all bounds agree with Table 3c to 3 decimals except two upper
    // variance bounds, where the paper divided by rounded chi2 points: 1-99 uses .554 (exact
    // 0.5543: 3.837, printed 3.839) and 5-95 uses 1.15 (exact 1.1455: 1.857, printed 1.849).
    const std::vector<double> v = table3aVInf(false);
    const SampleIntervals a = sampleIntervals(v, 0.01), b = sampleIntervals(v, 0.05),
                          c = sampleIntervals(v, 0.10);
    const struct {
        double got, want;
    } same[] = {{a.varianceLower, 0.141}, {a.sdLower, 0.375},       {a.sdUpper, 1.959},
                {a.meanLower, 7.977},     {a.meanUpper, 9.769},     {b.varianceLower, 0.192},
                {b.sdLower, 0.438},       {b.meanLower, 8.337},     {b.meanUpper, 9.410},
                {c.varianceLower, 0.230}, {c.varianceUpper, 1.321}, {c.sdLower, 0.480},
                {c.sdUpper, 1.149},       {c.meanLower, 8.480},     {c.meanUpper, 9.266}};
    for (const auto& s : same)
        QCOMPARE_LE(std::abs(s.got - s.want), 0.0005);
    // Documented deviations (rounded chi2 points in the paper), checked against 5 s^2 / chi2.
    QCOMPARE_LE(std::abs(a.varianceUpper - 3.837), 0.0005);
    QCOMPARE_LE(std::abs(b.varianceUpper - 1.857), 0.0005);
    QCOMPARE_LE(std::abs(b.sdUpper - 1.363), 0.0005); // printed 1.360
}

void TestFrictionStatistics::badInput() {
    QVERIFY(std::isnan(studentTQuantile(0.0, 5)));
    QVERIFY(std::isnan(studentTQuantile(0.5, -1)));
    QVERIFY(std::isnan(chiSquaredQuantile(1.0, 5)));
    QVERIFY(std::isnan(chiSquaredQuantile(0.5, 0)));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, grubbsTest({1.0, 2.0}));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, grubbsTest({1.0, 1.0, 1.0}));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, sampleIntervals({1.0}, 0.05));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, sampleIntervals({1.0, 2.0}, 0.7));
}

QTEST_APPLESS_MAIN(TestFrictionStatistics)
#include "tst_friction_statistics.moc"
