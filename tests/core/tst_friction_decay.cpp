// SPDX-License-Identifier: GPL-3.0-or-later
// The post-fracture decay law and its fit (Furgerson 1980 ch. III, Eqs. 2-5): the work
// abscissa, the closed-form regression, the V_inf minimization, and the paper's Table 3a/3b.

#include "FurgersonTables.h"

#include "core/friction/DecayFit.h"
#include "core/friction/DecayRegression.h"
#include "core/friction/WorkIntegral.h"
#include "core/numerics/BrentMinimize.h"

#include <Eigen/Dense>
#include <QtTest>

#include <cmath>

using namespace kinstab;

namespace {

const char* kRuns[] = {"30", "7", "43", "34", "36", "21", "11"}; // Table 3a column order

std::map<std::string, std::string> table3aFit(const std::string& run, const std::string& beta) {
    for (const auto& r : furgerson::rows("table3a_fits.csv"))
        if (r.at("run") == run && r.at("beta") == beta) return r;
    throw std::runtime_error("no Table 3a fit for run " + run);
}

TripletCurve sixRunMean() {
    std::vector<TripletCurve> runs;
    for (const char* r : kRuns)
        if (std::string(r) != "7") runs.push_back(furgerson::ng200Run(r));
    return compositeCurve(runs);
}

TripletCurve curveOf(const std::vector<double>& v) {
    TripletCurve c{"BJ-F-NG", 200, "T3b", Eigen::VectorXd::LinSpaced(9, 0.0, 0.4),
                   Eigen::VectorXd(9)};
    for (int i = 0; i < 9; ++i)
        c.shear(i) = v[i];
    return c;
}

} // namespace

class TestFrictionDecay : public QObject {
    Q_OBJECT
private slots:
    void brent();
    void workAbscissaExact();
    void closedFormMatchesWeightedLeastSquares();
    void recoversExactLaw_data();
    void recoversExactLaw();
    void table3aPerRun_data();
    void table3aPerRun();
    void table3aBetaThird();
    void table3bSixRunComposite();
    void table3bSevenRunIsInconsistent();
    void evaluateMatchesFittedSamples();
    void rejectsBadCurves();
};

void TestFrictionDecay::brent() {
    // Interior minimum of a parabola, and a monotone function whose minimum is the right bound.
    const MinimumResult m =
        brentMinimize([](double x) { return (x - 2.0) * (x - 2.0) + 1.0; }, 0.0, 5.0, 1e-12);
    QVERIFY(m.converged);
    QCOMPARE_LE(std::abs(m.x - 2.0), 1e-7);
    const MinimumResult e = brentMinimize([](double x) { return -x; }, 0.0, 1.0, 1e-12);
    QCOMPARE_LE(1.0 - e.x, 2 * (std::sqrt(2.2e-16) + 1e-12)); // Brent's stopping rule
}

void TestFrictionDecay::workAbscissaExact() {
    // Constant V: W = V d, xi = (3/4) V^(1/3) d^(4/3) (analytic).
    const Eigen::VectorXd d = Eigen::VectorXd::LinSpaced(9, 0.0, 0.4);
    const Eigen::VectorXd v = Eigen::VectorXd::Constant(9, 12.0);
    const Eigen::VectorXd xi = workAbscissa(d, v, 1.0 / 3.0);
    for (int i = 0; i < 9; ++i)
        QCOMPARE_LE(std::abs(xi(i) - 0.75 * std::cbrt(12.0) * std::pow(d(i), 4.0 / 3.0)), 1e-9);
    // Linear V = 20 - 25 d: W = 20 d - 12.5 d^2; reference by composite Simpson on 2e5 panels
    // after d = u^3 (an independent quadrature of the same integral).
    const Eigen::VectorXd vl = (20.0 - 25.0 * d.array()).matrix();
    const Eigen::VectorXd xl = workAbscissa(d, vl, 1.0 / 3.0);
    const auto f = [](double u) {
        const double s = u * u * u;
        return std::cbrt(20 * s - 12.5 * s * s) * 3 * u * u;
    };
    const int n = 200000;
    const double umax = std::cbrt(0.4), h = umax / n;
    double simpson = f(0) + f(umax);
    for (int k = 1; k < n; ++k)
        simpson += (k % 2 ? 4.0 : 2.0) * f(k * h);
    QCOMPARE_LE(std::abs(xl(8) - simpson * h / 3.0), 1e-9);
    // beta = 0: xi is the displacement from delta_1; W is the trapezoid sum.
    QCOMPARE_LE((workAbscissa(d, vl, 0.0) - d).norm(), 1e-15);
    QCOMPARE_LE(std::abs(cumulativeWork(d, vl)(8) - (20 * 0.4 - 12.5 * 0.16)), 1e-12);
}

void TestFrictionDecay::closedFormMatchesWeightedLeastSquares() {
    // Eqs. 3-4 in closed form against Eigen's QR solve of the weighted problem sqrt(w)[xi 1][c b] =
    // sqrt(w) eta.
    const TripletCurve run = furgerson::ng200Run("36");
    const Eigen::VectorXd xi = workAbscissa(run.delta, run.shear, 0.0);
    for (double alpha : {0.0, 2.0}) {
        const double vInf = 8.2;
        const DecayLine line = fitDecayLine(xi, run.shear, vInf, alpha);
        const Eigen::ArrayXd gap = run.shear.array() - vInf;
        const Eigen::VectorXd sw = gap.pow(0.5 * alpha).matrix();
        Eigen::MatrixXd a(9, 2);
        a.col(0) = sw.cwiseProduct(xi);
        a.col(1) = sw;
        const Eigen::VectorXd eta = (std::log(run.shear(0) - vInf) - gap.log()).matrix();
        const Eigen::Vector2d cb = a.colPivHouseholderQr().solve(sw.cwiseProduct(eta));
        QVERIFY(line.valid);
        QCOMPARE_LE(std::abs(line.c - cb(0)), 1e-10);
        QCOMPARE_LE(std::abs(line.b - cb(1)), 1e-12);
    }
}

void TestFrictionDecay::recoversExactLaw_data() {
    QTest::addColumn<double>("alpha");
    QTest::addColumn<double>("beta");
    QTest::newRow("synthetic alpha=2 beta=0") << 2.0 << 0.0;
    QTest::newRow("synthetic alpha=0 beta=0") << 0.0 << 0.0;
    QTest::newRow("synthetic alpha=2 beta=1/3") << 2.0 << 1.0 / 3.0;
}

void TestFrictionDecay::recoversExactLaw() {
    // Data made by the law itself (b = 0 so V(delta_1) = V_1; V_inf = 6 well below min V):
    // f_m = 0 at the true parameters, so the fit must return them. For beta = 1/3 the data are
    // built by fixed-point iteration (xi depends on V through W).
    QFETCH(double, alpha);
    QFETCH(double, beta);
    const double vInf = 6.0, c = beta == 0.0 ? 8.0 : 2.5, v1 = 16.0;
    TripletCurve curve{"synthetic", 100, "1", Eigen::VectorXd::LinSpaced(9, 0.0, 0.4),
                       Eigen::VectorXd::Constant(9, v1)};
    for (int it = 0; it < 200; ++it) {
        const Eigen::VectorXd xi = workAbscissa(curve.delta, curve.shear, beta);
        curve.shear = decayModel(xi, v1, vInf, DecayLine{c, 0.0, true});
    }
    DecayFitOptions o;
    o.alpha = alpha;
    const DecayFit fit = fitDecay(curve, beta, o);
    QCOMPARE_LE(std::abs(fit.vInf - vInf), 1e-4);
    QCOMPARE_LE(std::abs(fit.c - c), 1e-3);
    QCOMPARE_LE(std::abs(fit.b), 1e-4);
    QCOMPARE_LE(fit.fm, 1e-9);
    QVERIFY(!fit.atUpperBound);
}

void TestFrictionDecay::table3aPerRun_data() {
    QTest::addColumn<QString>("run");
    for (const char* r : kRuns)
        QTest::addRow("Table 3a run #%s", r) << QString(r);
}

void TestFrictionDecay::table3aPerRun() {
    // alpha = 2, beta = 0, each run of BJ-F-NG-200 (Table 1 = Table 3a, identical value by value).
    // V_inf to +-0.05 kip; b is printed to 2 decimals (+-0.005) and comes out within 0.01;
    // c within 5 % and f_m within 0.015 kip^2: the paper's f_m are ~0.01 higher throughout,
    // a difference we could not trace (the independent re-fit in cross_checks.txt agrees with
    // ours).
    QFETCH(QString, run);
    const auto want = table3aFit(run.toStdString(), "0");
    const DecayFit fit = fitDecay(furgerson::ng200Run(run.toStdString()), 0.0);
    const double vInf = std::stod(want.at("V_inf")), c = std::stod(want.at("c"));
    qInfo("run #%s: V_inf %.3f (paper %.2f)  c %.2f (%.2f)  b %.3f (%s)  f_m %.3f (%s)",
          qPrintable(run), fit.vInf, vInf, fit.c, c, fit.b, want.at("b").c_str(), fit.fm,
          want.at("f_m").c_str());
    QCOMPARE_LE(std::abs(fit.vInf - vInf), 0.05);
    QCOMPARE_LE(std::abs(fit.b - std::stod(want.at("b"))), 0.01);
    QCOMPARE_LE(std::abs(fit.c - c), 0.05 * c);
    QCOMPARE_LE(std::abs(fit.fm - std::stod(want.at("f_m"))), 0.015);
    QVERIFY(fit.atUpperBound); // f_m falls towards the bound V_inf < min V_i for every run
    // beta = 0 is the better law for every run (Table 3a: f_m 0.01-0.08 vs 0.05-0.32 for beta =
    // 1/3).
    QCOMPARE(fitDecayBestBeta(furgerson::ng200Run(run.toStdString())).beta, 0.0);
}

void TestFrictionDecay::table3aBetaThird() {
    // alpha = 2, beta = 1/3 (Table 3a, lower half). With the exact polyline quadrature b agrees
    // with the printed 2 decimals within 0.01 for all 7 runs (a plain trapezoid rule on W^(1/3)
    // gives b 0.02-0.03 too high: cross_checks.txt / TRANSCRIPTION_NOTES.md), c within 7 %.
    for (const char* run : kRuns) {
        const auto want = table3aFit(run, "1/3");
        const DecayFit fit = fitDecay(furgerson::ng200Run(run), 1.0 / 3.0);
        QCOMPARE_LE(std::abs(fit.b - std::stod(want.at("b"))), 0.01);
        QCOMPARE_LE(std::abs(fit.c - std::stod(want.at("c"))), 0.07 * std::stod(want.at("c")));
        QCOMPARE_LE(std::abs(fit.vInf - std::stod(want.at("V_inf"))), 0.05);
    }
}

void TestFrictionDecay::table3bSixRunComposite() {
    // Table 3b (iv): the mean curve of the 6 runs without #7, fitted: V_inf 8.87, c 10.79, b .033.
    // The report prints that curve rounded to 0.1 kip, so its digits carry that rounding; the
    // tolerance is how far rounding the exact mean to 0.1 kip moves each fitted parameter.
    const TripletCurve mean = sixRunMean();
    QCOMPARE_LE(std::abs(mean.shear(0) - 15.0), 0.05); // printed (iv) curve, delta = 0
    const DecayFit exact = fitDecay(mean, 0.0);
    TripletCurve rounded = mean;
    rounded.shear = (mean.shear * 10.0).array().round().matrix() / 10.0;
    const DecayFit r = fitDecay(rounded, 0.0);
    const double tolV = std::abs(r.vInf - exact.vInf), tolC = std::abs(r.c - exact.c),
                 tolB = std::abs(r.b - exact.b);
    qInfo("6-run composite: V_inf %.3f c %.3f b %.4f (paper 8.87 10.79 .033); rounding sensitivity "
          "%.3f %.3f %.4f",
          exact.vInf, exact.c, exact.b, tolV, tolC, tolB);
    QCOMPARE_LE(std::abs(exact.vInf - 8.87), tolV);
    QCOMPARE_LE(std::abs(exact.c - 10.79), tolC);
    QCOMPARE_LE(std::abs(exact.b - 0.033), tolB);
    QCOMPARE(std::round(exact.b * 1000.0), 33.0); // b to the printed digits
    // Composite V_inf agrees with the mean of the per-run V_inf (ch. III: "very good agreement",
    // Table 3b ii: 8.87).
    double meanRunVInf = 0.0;
    for (const char* run : kRuns)
        if (std::string(run) != "7")
            meanRunVInf += fitDecay(furgerson::ng200Run(run), 0.0).vInf / 6.0;
    QCOMPARE_LE(std::abs(meanRunVInf - exact.vInf), 0.02);
}

void TestFrictionDecay::table3bSevenRunIsInconsistent() {
    // Documented deviation (TRANSCRIPTION_NOTES.md, check 4): the printed 7-run curve (iii) is
    // 0.03-0.43 kip below the mean of the 7 Table 3a runs, and its printed fit (V_inf 9.13 +-0.12,
    // c 9.73, b 0.039) is reproduced from neither. The independent re-fit gives 9.34/10.63/0.031
    // (mean of the runs) and 9.30/10.85/0.029 (printed curve); we match those and not the paper.
    std::vector<TripletCurve> all;
    for (const char* run : kRuns)
        all.push_back(furgerson::ng200Run(run));
    const DecayFit ofMean = fitDecay(compositeCurve(all), 0.0);
    const DecayFit ofPrinted =
        fitDecay(curveOf({15.3, 12.3, 11.1, 10.4, 10.2, 9.8, 9.7, 9.4, 9.3}), 0.0);
    QCOMPARE_LE(std::abs(ofMean.vInf - 9.34), 0.005);
    QCOMPARE_LE(std::abs(ofMean.c - 10.63), 0.005);
    QCOMPARE_LE(std::abs(ofMean.b - 0.031), 0.0005);
    QCOMPARE_LE(std::abs(ofPrinted.vInf - 9.30), 0.005);
    QCOMPARE_LE(std::abs(ofPrinted.c - 10.85), 0.005);
    QCOMPARE_LE(std::abs(ofPrinted.b - 0.029), 0.0005);
    QCOMPARE_GT(std::abs(ofMean.vInf - 9.13), 0.12); // outside the paper's own +-0.12
    QCOMPARE_GT(std::abs(ofPrinted.vInf - 9.13), 0.12);
}

void TestFrictionDecay::evaluateMatchesFittedSamples() {
    const TripletCurve run = furgerson::ng200Run("21");
    for (double beta : {0.0, 1.0 / 3.0}) {
        const DecayFit fit = fitDecay(run, beta);
        const Eigen::VectorXd dense = Eigen::VectorXd::LinSpaced(81, 0.0, 0.4);
        const Eigen::VectorXd v = evaluateDecay(fit, run, dense);
        for (int i = 0; i < 9; ++i)
            QCOMPARE_LE(std::abs(v(10 * i) - fit.fitted(i)), 1e-10);
    }
}

void TestFrictionDecay::rejectsBadCurves() {
    TripletCurve flat{"X", 100, "1", Eigen::VectorXd::LinSpaced(4, 0.0, 0.3),
                      Eigen::VectorXd::Constant(4, 5.0)};
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, fitDecay(flat, 0.0));
    TripletCurve shortCurve{"X", 100, "2", Eigen::VectorXd::LinSpaced(2, 0.0, 0.1),
                            Eigen::VectorXd::Constant(2, 5.0)};
    QVERIFY(validateCurve(shortCurve).find("at least 3") != std::string::npos);
    TripletCurve back = furgerson::ng200Run("30");
    back.delta(3) = back.delta(2);
    QVERIFY(validateCurve(back).find("delta must increase") != std::string::npos);
    TripletCurve nan = furgerson::ng200Run("30");
    nan.shear(4) = std::nan("");
    QVERIFY(validateCurve(nan).find("not finite") != std::string::npos);
}

QTEST_APPLESS_MAIN(TestFrictionDecay)
#include "tst_friction_decay.moc"
