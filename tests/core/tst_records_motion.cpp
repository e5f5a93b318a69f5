// SPDX-License-Identifier: GPL-3.0-or-later
// RecordedMotion (docs/theory.md §3, §6): a linearly interpolated record as the slab's base motion.
// Its integrals are checked against the Cauchy formula integrated by Simpson's rule (exact for
// the piecewise-quadratic integrand), its crossings and bounds against dense sampling, and the
// exact solver driven by a record against an independent small-step integration.

#include "core/excitation/RecordedMotion.h"
#include "core/records/RecordReader.h"
#include "core/slab/ExactSolver.h"

#include <QtTest>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

using namespace kinstab;

namespace {

const std::string kRecords = KINSTAB_SOURCE_DIR "/resources/records/";

// The test's own interpolant of the samples (independent of RecordedMotion's).
struct Interp {
    std::vector<double> a;
    double h;
    double operator()(double tau) const {
        const double end = h * static_cast<double>(a.size() - 1);
        if (tau < 0.0 || tau > end) return 0.0;
        const auto k = std::min(static_cast<std::size_t>(tau / h), a.size() - 2);
        const double u = tau / h - static_cast<double>(k);
        return a[k] * (1.0 - u) + a[k + 1] * u;
    }
};

// int_{t0}^{t1} w(s) f(s) ds by Simpson's rule on pieces cut at the sample times.
template <class F> double simpson(const Interp& in, double t0, double t1, F&& w) {
    double sum = 0.0;
    double lo = t0;
    while (lo < t1) {
        double hi = std::min(t1, (std::floor(lo / in.h + 1e-9) + 1.0) * in.h);
        if (hi <= lo) hi = std::min(t1, lo + in.h);
        const double mid = 0.5 * (lo + hi);
        // Values from inside the piece, so the jump at the record's end is not sampled twice.
        const double eps = 1e-12 * (hi - lo);
        sum += (hi - lo) / 6.0 *
               (w(lo) * in(lo + eps) + 4.0 * w(mid) * in(mid) + w(hi) * in(hi - eps));
        lo = hi;
    }
    return sum;
}

// Independent reference: explicit small steps with the slab rules of docs/theory.md §4; each step
// uses the trapezoid of a, a stop is placed by linear interpolation of the velocity.
struct Reference {
    double tauC = std::nan("");
    double maxAbs = 0, residual = 0;
};

Reference smallSteps(const Interp& a, double mu, double limit, double step, double tauEnd) {
    Reference r;
    double x = 0, v = 0;
    int s = 0;
    for (double t = 0.0; t < tauEnd; t += step) {
        const double a0 = a(t), a1 = a(t + step);
        if (s == 0) {
            if (std::abs(a1) > mu)
                s = a1 > 0 ? -1 : 1; // onset: slides against a
            else
                continue;
            const double f =
                (std::abs(a1) - mu) / (std::abs(a1) - std::abs(a0)); // part of step slipping
            v = -(a1 + mu * s) * f * step / 2.0;
            x += v * f * step / 3.0;
        } else {
            const double vNew = v - step * ((a0 + a1) / 2.0 + mu * s);
            if (s * vNew > 0.0) {
                x += step * (v + vNew) / 2.0;
                v = vNew;
            } else {
                const double theta = v / (v - vNew);
                x += theta * step * v / 2.0;
                v = 0.0;
                s = std::abs(a1) > mu ? (a1 > 0 ? -1 : 1) : 0;
            }
        }
        r.maxAbs = std::max(r.maxAbs, std::abs(x));
        if (std::abs(x) > limit) {
            r.tauC = t + step; // resolution: one step
            break;
        }
    }
    r.residual = x;
    return r;
}

} // namespace

class TestRecordedMotion : public QObject {
    Q_OBJECT
private slots:
    void integralsMatchCauchyFormula();
    void crossingsAndBounds();
    void scaledToTargetPeak();
    void zeroAfterEnd();
    void pieceChosenAsByQuotient();
    void invalidInput();
    void exactSolverMatchesSmallSteps_data();
    void exactSolverMatchesSmallSteps();
};

void TestRecordedMotion::integralsMatchCauchyFormula() {
    const Accelerogram rec = readRecord(kRecords + "RSN77_SFERN_PUL164.AT2");
    const RecordedMotion m(rec, 0.099);
    const Interp in{rec.samples, rec.dt / 0.099};
    std::mt19937 gen(7);
    std::uniform_real_distribution<double> u(0.0, m.endTau() + 3.0);
    for (int i = 0; i < 300; ++i) {
        double t0 = u(gen), t1 = u(gen);
        if (i % 3 == 0) t1 = t0 + 0.37 * in.h; // inside one sample interval
        if (t1 < t0) std::swap(t0, t1);
        const double v = simpson(in, t0, t1, [](double) { return 1.0; });
        const double d = simpson(in, t0, t1, [t1](double s) { return t1 - s; }); // Cauchy
        QVERIFY2(
            std::abs(m.velocityChange(t0, t1) - v) <= 1e-12 * (1.0 + std::abs(v)),
            qPrintable(
                QString("%1 %2: %3 vs %4").arg(t0).arg(t1).arg(m.velocityChange(t0, t1)).arg(v)));
        QVERIFY2(std::abs(m.displacementChange(t0, t1) - d) <= 1e-11 * (1.0 + std::abs(d)),
                 qPrintable(QString("%1 %2: %3 vs %4")
                                .arg(t0)
                                .arg(t1)
                                .arg(m.displacementChange(t0, t1))
                                .arg(d)));
    }
}

// Crossings: every sign change of a - level on a dense grid of each segment is found (levels
// 0 and +-mu included), and a touch at an end point is not a crossing. Bounds hold.
void TestRecordedMotion::crossingsAndBounds() {
    Accelerogram rec;
    rec.dt = 0.01;
    rec.samples = {0.0, 0.8, -0.7, -0.2, 0.6, 0.6, 0.0, 0.3, -0.9, 0.1};
    const RecordedMotion m(rec, 0.1); // h = 0.1
    for (double level : {0.0, 0.6, -0.6, 0.25, -0.75}) {
        double lo = 0.0;
        int found = 0, expected = 0;
        while (lo < m.endTau()) {
            const double hi = m.segmentEnd(lo);
            QVERIFY(hi > lo && hi - lo <= m.sampleStep() * (1 + 1e-12));
            const Crossings c = m.crossings(level, lo, hi);
            for (int i = 0; i < c.n; ++i) {
                const double t = c.t[static_cast<std::size_t>(i)];
                QVERIFY(t > lo && t < hi);
                QCOMPARE_LT(std::abs(m.accel(t) - level), 1e-14);
            }
            found += c.n;
            const double fl = m.accel(lo + 1e-13) - level, fh = m.accel(hi - 1e-13) - level;
            expected += (fl < 0) != (fh < 0) && fl != 0 && fh != 0;
            QVERIFY(m.boundOn(lo, hi) >=
                    std::max(std::abs(m.accel(lo + 1e-13)), std::abs(m.accel(hi - 1e-13))));
            QVERIFY(m.boundAfter(lo) >= std::abs(m.accel(lo + 1e-13)));
            lo = hi;
        }
        QCOMPARE(found, expected);
    }
    QCOMPARE(m.crossings(0.6, 0.4, 0.5).n, 0); // touches 0.6 at 0.4 and stays: no sign change
    QCOMPARE(m.crossings(0.0, 0.0, 0.1).n, 0); // starts at 0 and rises: no crossing inside
    QCOMPARE(m.crossings(0.0, 0.1, 0.2).n, 1); // 0.8 -> -0.7 crosses 0 inside
    QCOMPARE(m.boundAfter(0.75), 0.9);         // suffix max from sample 7 on
    QCOMPARE(m.boundAfter(0.85), 0.9);
    QCOMPARE(m.peak(), 0.9);
}

void TestRecordedMotion::scaledToTargetPeak() {
    const Accelerogram rec = readRecord(kRecords + "RSN68_SFERN_PEL-UP.AT2");
    const RecordedMotion m(rec, 0.099, 0.5);
    QCOMPARE_LT(std::abs(m.peak() - 0.5), 1e-15);
    QCOMPARE_LT(std::abs(m.scale() - 0.5 / 0.1643), 1e-3 * m.scale()); // SOURCES.md: peak 0.1643 g
    const double t = 1234.5 * rec.dt / 0.099;
    QCOMPARE_LT(std::abs(m.accel(t) - m.scale() * 0.5 * (rec.samples[1234] + rec.samples[1235])),
                1e-15);
}

void TestRecordedMotion::zeroAfterEnd() {
    Accelerogram rec;
    rec.dt = 0.02;
    rec.samples = {0.0, 1.0, 2.0};
    const RecordedMotion m(rec, 0.1); // h = 0.2, end 0.4
    QCOMPARE(m.accel(m.endTau()), 2.0);
    QCOMPARE(m.accel(m.endTau() * (1 + 1e-15)), 0.0);
    QCOMPARE(m.boundAfter(0.41), 0.0);
    // After the end the velocity stays and the displacement grows linearly: v = 0.2*(0+2*1+2)/2.
    QCOMPARE_LT(std::abs(m.velocityChange(0.0, 5.0) - 0.4), 1e-15);
    QCOMPARE_LT(std::abs(m.displacementChange(m.endTau(), 5.0)), 1e-15);
    QVERIFY(m.segmentEnd(0.4) > 0.4);
}

// accel picks the piece by a product with 1/h and a table of knots (faster than the quotient): at
// every knot, one and two ulps either side, and random times, its value is bit-identical to the
// interpolant on the piece floor(tau / h) with the slope (a_{k+1} - a_k) / h, as before that
// change, and segmentEnd gives the next sample time as it did from that floor.
void TestRecordedMotion::pieceChosenAsByQuotient() {
    Accelerogram rec;
    rec.dt = 0.01;
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> sample(-0.5, 0.5);
    for (int i = 0; i < 3001; ++i)
        rec.samples.push_back(sample(rng));
    const RecordedMotion m(rec, 0.099);
    const std::vector<double>& a = m.samples();
    const double h = m.sampleStep();
    auto reference = [&](double tau) {
        const double kk = std::floor(tau / h);
        const std::size_t k =
            kk > 0.0 ? std::min(static_cast<std::size_t>(kk), a.size() - 2) : std::size_t{0};
        return a[k] + (a[k + 1] - a[k]) / h * (tau - h * static_cast<double>(k));
    };
    std::vector<double> times;
    for (std::size_t k = 0; k < a.size(); ++k) {
        const double knot = h * static_cast<double>(k);
        const double below = std::nextafter(knot, 0.0), above = std::nextafter(knot, 1e9);
        times.insert(times.end(),
                     {knot, below, above, std::nextafter(below, 0.0), std::nextafter(above, 1e9)});
    }
    std::uniform_real_distribution<double> tau(0.0, m.endTau());
    for (int i = 0; i < 20000; ++i)
        times.push_back(tau(rng));
    int checked = 0;
    for (double t : times) {
        if (t < 0.0 || t > m.endTau()) continue;
        QVERIFY2(m.accel(t) == reference(t), qPrintable(QString::number(t, 'g', 17)));
        ++checked;
        if (t == m.endTau()) continue; // segmentEnd has growing steps from there
        // The next sample time after t, as segmentEnd had it from the quotient's floor.
        const double kk = std::floor(t / h);
        double next = h * (kk + 1.0);
        if (next <= t) next = h * (kk + 2.0);
        QVERIFY2(m.segmentEnd(t) == std::min(next, m.endTau()),
                 qPrintable(QString::number(t, 'g', 17)));
    }
    QVERIFY(checked > 34000);
}

void TestRecordedMotion::invalidInput() {
    Accelerogram rec;
    rec.dt = 0.01;
    rec.samples = {0.0, 0.0, 0.0};
    QVERIFY(validateRecordedMotion(rec, 0.099, 0.5).find("all zeros") != std::string::npos);
    QVERIFY(validateRecordedMotion(rec, -1.0, {}).find("tstar") != std::string::npos);
    rec.samples = {0.0, std::nan("")};
    QVERIFY(validateRecordedMotion(rec, 0.099, {}).find("not a finite") != std::string::npos);
    rec.samples = {0.0, 1.0};
    QVERIFY(validateRecordedMotion(rec, 0.099, -2.0).find("target peak") != std::string::npos);
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, RecordedMotion(rec, 0.0));
}

void TestRecordedMotion::exactSolverMatchesSmallSteps_data() {
    QTest::addColumn<QString>("file");
    QTest::addColumn<double>("peak"); // target g
    QTest::addColumn<double>("mu");
    QTest::addColumn<double>("limit");
    QTest::newRow("PUL164 as recorded, mu 0.6") << "RSN77_SFERN_PUL164.AT2" << 0.0 << 0.6 << 1.0;
    QTest::newRow("PUL164 to 0.8 g, mu 0.6") << "RSN77_SFERN_PUL164.AT2" << 0.8 << 0.6 << 1.0;
    QTest::newRow("PUL164 to 0.65 g, mu 0.6") << "RSN77_SFERN_PUL164.AT2" << 0.65 << 0.6 << 1.0;
    QTest::newRow("ElCentro180 to 0.5 g, mu 0.3")
        << "RSN6_IMPVALL.I_I-ELC180.AT2" << 0.5 << 0.3 << 1.0;
    QTest::newRow("ElCentro180 as recorded, mu 0.1")
        << "RSN6_IMPVALL.I_I-ELC180.AT2" << 0.0 << 0.1 << 20.0;
    QTest::newRow("PUL164 as recorded, mu 0.4") << "RSN77_SFERN_PUL164.AT2" << 0.0 << 0.4 << 1.0;
    QTest::newRow("PUL164 to 2 g, mu 0.6") << "RSN77_SFERN_PUL164.AT2" << 2.0 << 0.6 << 1.0;
    QTest::newRow("Rinaldi228 as recorded, mu 0.5") << "Rinaldi228.AT2" << 0.0 << 0.5 << 1.0;
}

void TestRecordedMotion::exactSolverMatchesSmallSteps() {
    QFETCH(QString, file);
    QFETCH(double, peak);
    QFETCH(double, mu);
    QFETCH(double, limit);
    const Accelerogram rec = readRecord(kRecords + file.toStdString());
    const double tstar = 0.099;
    const RecordedMotion m(rec, tstar, peak > 0 ? std::optional<double>(peak) : std::nullopt);
    SlabParams p;
    p.mu = mu;
    p.limit = limit;
    const SlabResult r = solveExact(m, p);
    QVERIFY2(r.outcome != Outcome::Failed, r.failure.c_str());
    const Interp in{m.samples(), m.sampleStep()};
    const double tauEnd = (r.outcome == Outcome::Collapsed ? r.tauC : r.tauEnd) + 1.0;
    double prevErr = std::numeric_limits<double>::infinity();
    for (double div : {400.0, 3200.0}) {
        const Reference ref = smallSteps(in, mu, limit, m.sampleStep() / div, tauEnd + 50.0);
        const double err = r.outcome == Outcome::Collapsed
                               ? std::abs(ref.tauC - r.tauC)
                               : std::abs(ref.residual - r.residualDelta);
        qInfo("%s step h/%g: exact %s tau_c %.10g max|d| %.10g res %.10g | ref tau_c %.10g max|d| "
              "%.10g res %.10g",
              qPrintable(file), div, outcomeName(r.outcome).c_str(), r.tauC, r.maxAbsDelta,
              r.residualDelta, ref.tauC, ref.maxAbs, ref.residual);
        QCOMPARE(std::isnan(ref.tauC), r.outcome != Outcome::Collapsed);
        QVERIFY2(std::abs(ref.maxAbs - r.maxAbsDelta) <= 2e-3 * (0.1 + r.maxAbsDelta) * 400.0 / div,
                 "max |delta| differs");
        QVERIFY(err <= prevErr);
        prevErr = err;
    }
    QVERIFY2(prevErr < 1e-3, qPrintable(QString::number(prevErr)));
}

QTEST_APPLESS_MAIN(TestRecordedMotion)
#include "tst_records_motion.moc"
