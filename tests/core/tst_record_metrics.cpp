// SPDX-License-Identifier: GPL-3.0-or-later
// Record metadata (core/excitation/RecordMetrics): PGA, PGV, PGD, Arias intensity, D5-95, mean
// period and Sa(T, 5 %), each against a closed form on a synthetic record and against an
// independent NumPy calculation on a shipped record (El Centro 1940, PEER RSN 6, 180).

#include "core/base/PhysicalConstants.h"
#include "core/excitation/RecordMetrics.h"
#include "core/io/StudySpecJson.h"
#include "core/records/RecordReader.h"
#include "core/study/StudyRecordMetrics.h"

#include <QtTest>

#include <cmath>
#include <numbers>

using namespace kinstab;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kG = kStandardGravity;

// sum_k amplitude_k sin(2 pi f_k t) sampled every dt from t = 0, n samples.
Accelerogram sines(double dt, std::size_t n, std::vector<std::pair<double, double>> parts) {
    Accelerogram a;
    a.dt = dt;
    a.samples.resize(n);
    for (std::size_t i = 0; i < n; ++i)
        for (const auto& [amplitude, f] : parts)
            a.samples[i] += amplitude * std::sin(2 * kPi * f * dt * static_cast<double>(i));
    return a;
}

void closeRel(double actual, double expected, double rel) {
    QCOMPARE_LE(std::abs(actual - expected), rel * std::abs(expected));
}

} // namespace

class TestRecordMetrics : public QObject {
    Q_OBJECT
private slots:
    void sineClosedForms();
    void meanPeriodOfLineSpectra();
    void spectralAccelerationOfAStep();
    void elCentroAgainstNumpy();
    void zeroRecordHasNoDuration();
    void studyRecordsAsTheSuiteGivesThem();
};

// a = A sin(2 pi f t) from rest, A = 0.3 g, f = 1 Hz, 20 s: v = A g (1 - cos w t) / w, so
// PGV = 2 A g / w; d = A g (t - sin(w t) / w) / w grows to PGD = A g 20 s / w at the end;
// integral a^2 over whole periods = (A g)^2 T / 2, Ia = pi / (2 g) (A g)^2 10 s; the Husid
// integral is (A g)^2 t / 2 at every half period, so t5 = 1 s, t95 = 19 s, D5-95 = 18 s. The
// sampled (piecewise-linear) sine differs by O((w dt)^2) = 1e-3 relative at dt = 1/200 s.
void TestRecordMetrics::sineClosedForms() {
    const double A = 0.3, w = 2 * kPi;
    const RecordMetrics m = recordMetrics(sines(1.0 / 200, 4001, {{A, 1.0}}));
    closeRel(m.pga, A, 1e-12);
    closeRel(m.pgv, 2 * A * kG / w, 2e-4);
    closeRel(m.pgd, A * kG * 20.0 / w, 2e-4);
    QCOMPARE_LT(std::abs(m.finalVelocity), 1e-3 * m.pgv);
    closeRel(m.arias, kPi / (2 * kG) * std::pow(A * kG, 2) * 10.0, 2e-4);
    QVERIFY(m.t5 && m.t95 && m.d5_95);
    QCOMPARE_LT(std::abs(*m.t5 - 1.0), 2e-3);
    QCOMPARE_LT(std::abs(*m.t95 - 19.0), 2e-3);
    QCOMPARE_LT(std::abs(*m.d5_95 - 18.0), 4e-3);
    QVERIFY(!m.sa);
}

// Sines on DFT bins (4096 samples of 1/128 s: bins every 1/32 Hz) have line spectra, so Rathje's
// Tm = sum C^2 / f / sum C^2 is exact: 1 s for 1 Hz alone; (A1^2 / 1 + A2^2 / 4) / (A1^2 + A2^2)
// for 1 Hz and 4 Hz; a 0.125 Hz line lies outside 0.25-20 Hz and does not count.
void TestRecordMetrics::meanPeriodOfLineSpectra() {
    const double dt = 1.0 / 128;
    const RecordMetrics one = recordMetrics(sines(dt, 4096, {{0.2, 1.0}}));
    QVERIFY(one.meanPeriod);
    closeRel(*one.meanPeriod, 1.0, 1e-9);
    const RecordMetrics two =
        recordMetrics(sines(dt, 4096, {{0.2, 1.0}, {0.4, 4.0}, {0.3, 0.125}}));
    QVERIFY(two.meanPeriod);
    closeRel(*two.meanPeriod, (0.04 / 1.0 + 0.16 / 4.0) / (0.04 + 0.16), 1e-9);
}

// A constant acceleration a0 from rest (a step: linear between samples, so the recurrence is
// exact). Undamped, x = -(a0 / w^2)(1 - cos w t) and the absolute acceleration -w^2 x peaks at
// 2 a0 at t = T / 2, a sample time at dt = T / 2000. Damped, the response overshoots by
// exp(-pi z / sqrt(1 - z^2)) (Chopra, Dynamics of Structures, step response), so Sa lies between
// a0 (1 + that) and 2 a0.
void TestRecordMetrics::spectralAccelerationOfAStep() {
    const double T = 0.8, a0 = 0.25;
    Accelerogram a;
    a.dt = T / 2000;
    a.samples.assign(4000, a0);
    closeRel(spectralAcceleration(a, T, 0.0), 2 * a0, 1e-9);
    const double z = kSpectralDamping;
    const RecordMetrics m = recordMetrics(a, T);
    QVERIFY(m.sa);
    QCOMPARE(m.sa->period, T);
    QCOMPARE(m.sa->damping, 0.05);
    QVERIFY(m.sa->g > a0 * (1 + std::exp(-kPi * z / std::sqrt(1 - z * z))));
    QVERIFY(m.sa->g < 2 * a0);
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, spectralAcceleration(a, 0.0, z));
}

// Independent calculation (NumPy, written apart from the C++; run on
// resources/records/RSN6_IMPVALL.I_I-ELC180.AT2):
//   a = samples (g); am = a * 9.80665
//   v = cumsum of (am[1:] + am[:-1]) / 2 dt;  d = cumsum of v[:-1] dt + (2 am[:-1] + am[1:]) dt^2/6
//   c = cumsum of dt (am0^2 + am0 am1 + am1^2) / 3;  Ia = pi / (2 g) c[-1]
//   t5, t95 = np.interp([0.05 c[-1], 0.95 c[-1]], c, t)
//   n = next power of 2 >= max(len(a), 1 / (0.05 dt)); C = |np.fft.rfft(a, n)|,
//   f = np.fft.rfftfreq(n, dt), 0.25 <= f <= 20: Tm = sum C^2 / f / sum C^2
//   Sa: state [x, v, a, a'] with M = [[0,1,0,0],[-w^2,-2zw,-1,0],[0,0,0,1],[0,0,0,0]],
//       E = expm(M dt) (scaling and squaring, 20 Taylor terms), stepped from rest over each
//       sample interval with a' = (a[i] - a[i-1]) / dt; Sa = max |2 z w v + w^2 x|.
// printed: pga 0.2807955 pgv 0.309286895 pgd 0.08661894194 arias 1.541858564 t5 2.120163266
//          t95 26.3084694 Tm 0.5787257477 Sa(0.2) 0.6273989938 Sa(1.0) 0.4728542132
//          Sa(2.0) 0.1985421415.
void TestRecordMetrics::elCentroAgainstNumpy() {
    const Accelerogram a =
        readRecord(KINSTAB_SOURCE_DIR "/resources/records/RSN6_IMPVALL.I_I-ELC180.AT2");
    const RecordMetrics m = recordMetrics(a, 1.0);
    closeRel(m.pga, 0.2807955, 1e-9);
    closeRel(m.pgv, 0.309286895, 1e-8);
    closeRel(m.pgd, 0.08661894194, 1e-8);
    closeRel(m.arias, 1.541858564, 1e-8);
    closeRel(*m.t5, 2.120163266, 1e-8);
    closeRel(*m.t95, 26.3084694, 1e-8);
    closeRel(*m.d5_95, 26.3084694 - 2.120163266, 1e-8);
    closeRel(*m.meanPeriod, 0.5787257477, 1e-8);
    closeRel(m.sa->g, 0.4728542132, 1e-7);
    closeRel(spectralAcceleration(a, 0.2, 0.05), 0.6273989938, 1e-7);
    closeRel(spectralAcceleration(a, 2.0, 0.05), 0.1985421415, 1e-7);
}

void TestRecordMetrics::zeroRecordHasNoDuration() {
    Accelerogram a;
    a.dt = 0.01;
    a.samples.assign(500, 0.0);
    const RecordMetrics m = recordMetrics(a, 1.0);
    QCOMPARE(m.pga, 0.0);
    QCOMPARE(m.arias, 0.0);
    QVERIFY(!m.d5_95 && !m.t5 && !m.meanPeriod);
    QCOMPARE(m.sa->g, 0.0);
}

// A study's record table: each record times its scale (PGA and PGV scale with it, Arias with its
// square), Sa at the study's Sa period, none for a PGA study without floor filters.
void TestRecordMetrics::studyRecordsAsTheSuiteGivesThem() {
    const std::string elCentro =
        KINSTAB_SOURCE_DIR "/resources/records/RSN6_IMPVALL.I_I-ELC180.AT2";
    const std::string text = R"({"format": "kinstab-study", "version": 1,
        "records": [{"path": ")" +
                             elCentro + R"(", "scale": 2},
                    {"path": ")" +
                             elCentro + R"("}],
        "intensity": {"measure": "sa", "period_s": 1.0},
        "parameters": {"mu": [0.6], "tstar": [0.099]}})";
    const StudySpec spec = studyFromJsonText(text, "");
    QCOMPARE(studySaPeriod(spec), std::optional<double>(1.0));
    const std::vector<StudyRecordMetrics> m = studyRecordMetrics(spec);
    QCOMPARE(m.size(), std::size_t(2));
    QCOMPARE(m[1].record, spec.records[1].label);
    closeRel(m[1].metrics.pga, 0.2807955, 1e-9); // the NumPy figures above
    closeRel(m[1].metrics.sa->g, 0.4728542132, 1e-7);
    closeRel(m[0].metrics.pga, 2 * 0.2807955, 1e-9);
    closeRel(m[0].metrics.pgv, 2 * 0.309286895, 1e-8);
    closeRel(m[0].metrics.arias, 4 * 1.541858564, 1e-8);
    closeRel(m[0].metrics.sa->g, 2 * 0.4728542132, 1e-7);
    closeRel(*m[0].metrics.d5_95, *m[1].metrics.d5_95, 1e-12); // a scale keeps the shape
    const StudySpec pga =
        studyFromJsonText(R"({"format": "kinstab-study", "version": 1, "records": [{"path": ")" +
                              elCentro + R"("}], "parameters": {"mu": [0.6], "tstar": [0.099]}})",
                          "");
    QVERIFY(!studySaPeriod(pga));
    QVERIFY(!studyRecordMetrics(pga)[0].metrics.sa);
}

QTEST_APPLESS_MAIN(TestRecordMetrics)
#include "tst_record_metrics.moc"
