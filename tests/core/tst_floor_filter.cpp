// SPDX-License-Identifier: GPL-3.0-or-later
// The floor filter (docs/theory.md §7, paper eq. 6) and the spectra and envelope of Figs. 25-27.
//  - Nigam-Jennings recurrence vs the closed-form harmonic steady state (to 1e-6);
//  - vs an independent RK4 integration with fine sub-steps on a real record;
//  - the paper's observation (Figs. 25-26): the floor motion of the Pacoima Dam record through
//    a 1 Hz, 2 % oscillator is "composed for the most part of one frequency", 1/T;
//  - the envelope fit recovers alpha, beta of a synthetic enveloped sine.

#include "core/excitation/EnvelopeFit.h"
#include "core/excitation/FloorFilter.h"
#include "core/excitation/FourierSpectrum.h"
#include "core/records/RecordReader.h"

#include <QtTest>

#include <complex>
#include <numbers>

using namespace kinstab;

namespace {

const std::string kRecords = KINSTAB_SOURCE_DIR "/resources/records/";
constexpr double kPi = std::numbers::pi;

// Steady state of x'' + 2 z w x' + w^2 x = -A sin(W t): x = Im(X e^{iWt}), X = -A / (w^2 - W^2 + 2i
// z w W).
struct SteadyState {
    std::complex<double> X;
    double w, z, W;
    double x(double t) const { return std::imag(X * std::polar(1.0, W * t)); }
    double v(double t) const {
        return std::imag(std::complex<double>(0, W) * X * std::polar(1.0, W * t));
    }
    double absAccel(double t) const { return -(2.0 * z * w * v(t) + w * w * x(t)); }
};

SteadyState steadyState(double period, double zeta, double forcingHz, double amplitude) {
    const double w = 2 * kPi / period, W = 2 * kPi * forcingHz;
    return {-amplitude / std::complex<double>(w * w - W * W, 2 * zeta * w * W), w, zeta, W};
}

} // namespace

class TestFloorFilter : public QObject {
    Q_OBJECT
private slots:
    void harmonicSteadyState_data();
    void harmonicSteadyState();
    void harmonicFromRestAfterTransient();
    void matchesFineRk4OnRecord();
    void paperFig25and26FloorMotionIsOneFrequency();
    void spectrumOfBinSine();
    void envelopeFitRecoversSyntheticEnvelope_data();
    void envelopeFitRecoversSyntheticEnvelope();
    void floorMotionTailAndValidation();
    void shortestPeriodIsTheGround();
};

void TestFloorFilter::harmonicSteadyState_data() {
    QTest::addColumn<double>("period");
    QTest::addColumn<double>("zeta");
    QTest::addColumn<double>("forcingHz");
    QTest::newRow("T1 z0.02 below resonance 0.5Hz") << 1.0 << 0.02 << 0.5;
    QTest::newRow("T1 z0.02 at resonance 1Hz") << 1.0 << 0.02 << 1.0;
    QTest::newRow("T1 z0.02 above resonance 2Hz") << 1.0 << 0.02 << 2.0;
    QTest::newRow("T0.3 z0.05 3Hz") << 0.3 << 0.05 << 3.0;
    QTest::newRow("T2 z0 undamped 0.7Hz") << 2.0 << 0.0 << 0.7;
}

// Started on the steady-state orbit, the filtered sampled sine stays on it; the only error is
// the linear interpolation of the sine between samples, (W dt)^2 / 8 ~ 2e-7 here.
void TestFloorFilter::harmonicSteadyState() {
    QFETCH(double, period);
    QFETCH(double, zeta);
    QFETCH(double, forcingHz);
    const double dt = 1e-4, amplitude = 0.3;
    const SteadyState ss = steadyState(period, zeta, forcingHz, amplitude);
    std::vector<double> ground(static_cast<std::size_t>(5.0 / forcingHz / dt));
    for (std::size_t i = 0; i < ground.size(); ++i)
        ground[i] = amplitude * std::sin(ss.W * dt * static_cast<double>(i));
    const std::vector<double> y = floorAcceleration(ground, dt, period, zeta, {ss.x(0), ss.v(0)});
    const double scale =
        amplitude *
        std::abs(std::complex<double>(ss.w * ss.w, 2 * zeta * ss.w * ss.W) /
                 std::complex<double>(ss.w * ss.w - ss.W * ss.W, 2 * zeta * ss.w * ss.W));
    double err = 0.0;
    for (std::size_t i = 0; i < y.size(); ++i)
        err = std::max(err, std::abs(y[i] - ss.absAccel(dt * static_cast<double>(i))));
    qInfo("max relative error %.3g (steady amplitude %.6g g)", err / scale, scale);
    QVERIFY(err <= 1e-6 * scale);
}

void TestFloorFilter::harmonicFromRestAfterTransient() {
    const double period = 0.5, zeta = 0.2, f = 1.3, dt = 1e-4, amplitude = 1.0;
    const SteadyState ss = steadyState(period, zeta, f, amplitude);
    // Transient decays as exp(-zeta w t): below 1e-9 after 20 / (zeta w) = 8 s.
    const double tEnd = 10.0;
    std::vector<double> ground(static_cast<std::size_t>(tEnd / dt));
    for (std::size_t i = 0; i < ground.size(); ++i)
        ground[i] = amplitude * std::sin(ss.W * dt * static_cast<double>(i));
    const std::vector<double> y = floorAcceleration(ground, dt, period, zeta);
    double err = 0.0, top = 0.0;
    for (std::size_t i = ground.size() - static_cast<std::size_t>(1.0 / f / dt); i < y.size();
         ++i) {
        err = std::max(err, std::abs(y[i] - ss.absAccel(dt * static_cast<double>(i))));
        top = std::max(top, std::abs(y[i]));
    }
    QVERIFY2(err <= 1e-6 * top, qPrintable(QString::number(err / top)));
}

// Independent reference: RK4 on the first-order system with the record linearly interpolated,
// 64 sub-steps per sample (error ~ (w h)^4 / 120 ~ 1e-12).
void TestFloorFilter::matchesFineRk4OnRecord() {
    Accelerogram rec = readRecord(kRecords + "RSN77_SFERN_PUL164.AT2");
    rec.samples.resize(1500);
    const double T = 1.0, z = 0.02, w = 2 * kPi / T;
    const std::vector<double> y = floorAcceleration(rec.samples, rec.dt, T, z);
    double x = 0, v = 0, err = 0, top = 0;
    const int sub = 64;
    const double h = rec.dt / sub;
    for (std::size_t i = 0; i + 1 < rec.samples.size(); ++i) {
        const double g0 = rec.samples[i], g1 = rec.samples[i + 1];
        auto g = [&](double s) { return g0 + (g1 - g0) * s / rec.dt; };
        auto f = [&](double s, double xx, double vv) {
            return -g(s) - 2 * z * w * vv - w * w * xx;
        };
        for (int k = 0; k < sub; ++k) {
            const double s = k * h;
            const double k1x = v, k1v = f(s, x, v);
            const double k2x = v + h / 2 * k1v,
                         k2v = f(s + h / 2, x + h / 2 * k1x, v + h / 2 * k1v);
            const double k3x = v + h / 2 * k2v,
                         k3v = f(s + h / 2, x + h / 2 * k2x, v + h / 2 * k2v);
            const double k4x = v + h * k3v, k4v = f(s + h, x + h * k3x, v + h * k3v);
            x += h / 6 * (k1x + 2 * k2x + 2 * k3x + k4x);
            v += h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
        }
        const double yRef = -(2 * z * w * v + w * w * x);
        err = std::max(err, std::abs(y[i + 1] - yRef));
        top = std::max(top, std::abs(yRef));
    }
    QVERIFY2(err <= 1e-9 * top, qPrintable(QString::number(err / top)));
}

// Paper ch. IV: the Pacoima Dam 1971 record (here NGA RSN77 164 deg = S16E, same instrument;
// the paper's "S14W" is not one of the two published azimuths, S16E and S74W) through a 1 Hz, 2 %
// oscillator, 10.24 s analysed (the paper: 512 points over 10.22 s). "The response of the absolute
// acceleration is composed for the most part of one frequency": the floor's largest spectral peak
// sits at 1/T, and most of its energy lies within +-20 % of it, while the ground motion's does not.
void TestFloorFilter::paperFig25and26FloorMotionIsOneFrequency() {
    Accelerogram ground = readRecord(kRecords + "RSN77_SFERN_PUL164.AT2");
    const Accelerogram floor = floorMotion(ground, {1.0, 0.02, 0.0});
    const std::size_t n = static_cast<std::size_t>(10.24 / ground.dt);
    const std::vector<double> g(ground.samples.begin(),
                                ground.samples.begin() + static_cast<long>(n));
    const std::vector<double> f(floor.samples.begin(),
                                floor.samples.begin() + static_cast<long>(n));
    const AmplitudeSpectrum sg = amplitudeSpectrum(g, ground.dt),
                            sf = amplitudeSpectrum(f, ground.dt);
    QCOMPARE(sf.points, std::size_t(1024));
    const SpectrumPeak top = spectrumPeaks(sf, 1).front();
    const double eFloor = bandEnergyFraction(sf, 0.8, 1.2),
                 eGround = bandEnergyFraction(sg, 0.8, 1.2);
    qInfo("floor peak %.3f Hz; energy in 0.8-1.2 Hz: floor %.3f ground %.3f; ground peaks %.2f "
          "%.2f %.2f Hz",
          top.frequency, eFloor, eGround, spectrumPeaks(sg, 3)[0].frequency,
          spectrumPeaks(sg, 3)[1].frequency, spectrumPeaks(sg, 3)[2].frequency);
    QCOMPARE_LE(std::abs(top.frequency - 1.0), sf.df);
    QVERIFY(eFloor > 0.5);
    QVERIFY(eGround < 0.5 * eFloor);
}

void TestFloorFilter::spectrumOfBinSine() {
    const double dt = 0.02;
    std::vector<double> x(512);
    for (std::size_t i = 0; i < x.size(); ++i)
        x[i] = 0.7 * std::sin(2 * kPi * 25.0 * static_cast<double>(i) / 512.0);
    const AmplitudeSpectrum s = amplitudeSpectrum(x, dt);
    QCOMPARE(s.points, std::size_t(512));
    QCOMPARE_LT(std::abs(s.df - 1.0 / (512 * dt)), 1e-15);
    QCOMPARE_LT(std::abs(s.amplitude[25] - 1.0), 1e-12);
    for (std::size_t k = 0; k < s.amplitude.size(); ++k)
        if (k != 25) QVERIFY2(s.amplitude[k] < 1e-12, qPrintable(QString::number(k)));
    QCOMPARE_LT(std::abs(spectrumPeaks(s, 3).front().frequency - 25.0 * s.df), 1e-12);
}

void TestFloorFilter::envelopeFitRecoversSyntheticEnvelope_data() {
    QTest::addColumn<double>("alpha");
    QTest::addColumn<double>("beta");
    QTest::addColumn<double>("hz");
    // docs/theory.md §3 presets. The fast envelope rises in ~0.5 s: at 1 Hz only one half cycle
    // samples the rise and beta is undetermined, so that row uses 5 Hz (several peaks on the rise).
    QTest::newRow("moderate 0.15 0.40 at 1 Hz") << 0.15 << 0.40 << 1.0;
    QTest::newRow("slow 0.04 0.40 at 1 Hz") << 0.04 << 0.40 << 1.0;
    QTest::newRow("fast 0.01 2.0 at 5 Hz") << 0.01 << 2.0 << 5.0;
}

// 0.5 e(t) sin(2 pi f t), sampled at 0.005 s for 120 s: the half-cycle peaks lie on the envelope
// to O(e'/e / omega), so the fit returns alpha, beta to about a per cent.
void TestFloorFilter::envelopeFitRecoversSyntheticEnvelope() {
    QFETCH(double, alpha);
    QFETCH(double, beta);
    QFETCH(double, hz);
    Accelerogram m;
    m.dt = 0.005;
    for (int i = 0; i < 24000; ++i) {
        const double t = m.dt * i;
        m.samples.push_back(0.5 * (std::exp(-alpha * t) - std::exp(-beta * t)) *
                            std::sin(2 * kPi * hz * t));
    }
    const EnvelopeFit fit = fitEnvelope(m);
    qInfo("alpha %.5f beta %.5f scale %.5f rms %.2g", fit.alpha, fit.beta, fit.scale, fit.rms);
    QCOMPARE_LE(std::abs(fit.alpha - alpha), 0.02 * alpha);
    QCOMPARE_LE(std::abs(fit.beta - beta), 0.02 * beta);
    QCOMPARE_LE(std::abs(fit.scale - 0.5), 0.01);
}

void TestFloorFilter::floorMotionTailAndValidation() {
    const Accelerogram ground = readRecord(kRecords + "RSN68_SFERN_PEL-UP.AT2");
    const Accelerogram floor = floorMotion(ground, {1.0, 0.02, std::nullopt});
    // Default tail: ln 100 / (zeta w) = 36.6 s for T = 1 s, 2 %.
    const double tail = std::log(100.0) / (0.02 * 2 * kPi);
    QCOMPARE(floor.size(), ground.size() + static_cast<std::size_t>(std::ceil(tail / ground.dt)));
    QCOMPARE_LT(std::abs(floor.samples.back()), 0.02 * std::abs(floor.peak().value));
    QVERIFY(!validateFloorFilter({-1.0, 0.02, {}}).empty());
    QVERIFY(!validateFloorFilter({1.0, 1.0, {}}).empty());
    QVERIFY(!validateFloorFilter({1.0, std::nan(""), {}}).empty());
    QVERIFY(!validateFloorFilter({1.0, 0.02, -3.0}).empty());
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, floorMotion(ground, {0.0, 0.02, {}}));
}

// Issue 31: 1e-300 s overflowed the recurrence into NaN samples (a floor peak of 0.0, exit 0).
// The period's lower bound, 0.01 s, is a rigid oscillator for any record: its floor motion is
// the ground's (the record's content lies far below 100 Hz), finite, and its peak within 2 % of
// the ground's.
void TestFloorFilter::shortestPeriodIsTheGround() {
    QCOMPARE(validateFloorFilter({1e-300, 0.02, {}}),
             std::string("floor period 1e-300 s: must be at least 0.01 s and at most 1000 s"));
    QVERIFY(!validateFloorFilter({0.0099, 0.02, {}}).empty());
    QVERIFY(!validateFloorFilter({1000.5, 0.02, {}}).empty());
    QVERIFY(validateFloorFilter({kMinFloorPeriodS, 0.02, {}}).empty());
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                             floorMotion(Accelerogram{}, {1e-300, 0.02, {}}));
    const Accelerogram ground = readRecord(kRecords + "RSN77_SFERN_PUL164.AT2");
    const Accelerogram floor = floorMotion(ground, {kMinFloorPeriodS, 0.02, std::nullopt});
    for (double a : floor.samples)
        QVERIFY(std::isfinite(a));
    const double g = std::abs(ground.peak().value), f = std::abs(floor.peak().value);
    QVERIFY2(std::abs(f - g) <= 0.02 * g,
             qPrintable(QString("floor %1 g, ground %2 g").arg(f).arg(g)));
}

QTEST_APPLESS_MAIN(TestFloorFilter)
#include "tst_floor_filter.moc"
