// SPDX-License-Identifier: GPL-3.0-or-later
// A seeded random walk over the documented input ranges of the 1-DOF model (README, "Numerics":
// f 0.01-100 Hz, A up to 100 g, mu from near 0 to above the peak, the three envelopes and
// custom ones, walls of 3-12 in): every run ends with a defined outcome and every number it
// promises is finite (tau_c when collapsed, the residual when stable). A sample is replayed by
// the independent quadrature solver of QuadratureReference.h.

#include "QuadratureReference.h"
#include "core/excitation/EnvelopedSine.h"
#include "core/slab/ExactSolver.h"
#include "core/slab/FiniteResult.h"
#include "core/slab/Slab1DCase.h"

#include <QtTest>
#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <thread>
#include <vector>

using namespace kinstab;

namespace {

struct RandomCase {
    Envelope envelope;
    double tstar = 0.099, amplitude = 1, frequency = 1, mu = 0.6;
    std::string name() const {
        return envelope.name() + ", t* " + std::to_string(tstar) + ", A " +
               std::to_string(amplitude) + ", f " + std::to_string(frequency) + ", mu " +
               std::to_string(mu);
    }
};

double logUniform(std::mt19937_64& g, double lo, double hi) {
    std::uniform_real_distribution<double> u(std::log(lo), std::log(hi));
    return std::exp(u(g));
}

RandomCase drawCase(std::mt19937_64& g) {
    RandomCase c;
    std::uniform_int_distribution<int> kind(0, 3);
    const int k = kind(g);
    if (k < 3) {
        c.envelope = Envelope::fromPreset(static_cast<EnvelopePreset>(k));
    } else {
        // A custom envelope with decay (alpha > 0: without it a run needs a duration).
        const double alpha = logUniform(g, 1e-2, 1.0);
        c.envelope = Envelope{alpha, alpha * (1.0 + logUniform(g, 1e-2, 100.0)), std::nullopt};
    }
    c.tstar = tstarFromWallWidthInches(logUniform(g, 3.0, 12.0));
    c.frequency = logUniform(g, 0.01, 100.0);
    c.mu = logUniform(g, 1e-2, 2.0);
    // A/mu from 0.5 (never slips) to 200 (collapses at once), A at most 100 g.
    c.amplitude = std::min(100.0, c.mu * logUniform(g, 0.5, 200.0));
    return c;
}

SlabResult solve(const RandomCase& c, const EnvelopedSine& a) {
    SlabParams p;
    p.mu = c.mu;
    return solveExact(a, p);
}

constexpr std::uint64_t kSeed = 20261124;

} // namespace

class TestRandomizedInvariants : public QObject {
    Q_OBJECT
private slots:
    void everyResultIsFiniteAndDefined() {
        // The cases are drawn in order from one seed, then run on a few threads (each run is
        // independent); the checks are made here, in the test's thread.
        constexpr int kCases = 10000;
        std::mt19937_64 g(kSeed);
        std::vector<RandomCase> cases;
        for (int i = 0; i < kCases; ++i)
            cases.push_back(drawCase(g));
        std::vector<SlabResult> results(cases.size());
        std::atomic<std::size_t> next{0};
        auto worker = [&] {
            for (std::size_t i; (i = next.fetch_add(1)) < cases.size();) {
                const EnvelopedSine a(cases[i].envelope, cases[i].amplitude, cases[i].frequency,
                                      cases[i].tstar);
                results[i] = solve(cases[i], a);
            }
        };
        std::vector<std::thread> pool;
        const unsigned threads = std::clamp(std::thread::hardware_concurrency(), 1u, 4u);
        for (unsigned t = 1; t < threads; ++t)
            pool.emplace_back(worker);
        worker();
        for (std::thread& t : pool)
            t.join();
        int collapsed = 0, stable = 0;
        for (std::size_t i = 0; i < cases.size(); ++i) {
            const SlabResult& r = results[i];
            const std::string where = "case " + std::to_string(i) + " (" + cases[i].name() + ")";
            QVERIFY2(nonFiniteField(r).empty(), (where + ": " + nonFiniteField(r)).c_str());
            QVERIFY2(r.outcome == Outcome::Stable || r.outcome == Outcome::Collapsed,
                     (where + ": " + outcomeName(r.outcome) + " " + r.failure).c_str());
            if (r.outcome == Outcome::Collapsed) {
                ++collapsed;
                QVERIFY2(r.tauC > 0.0 && r.tauC <= r.tauEnd, where.c_str());
            } else {
                ++stable;
                QVERIFY2(std::abs(r.residualDelta) <= 1.0, where.c_str());
            }
            QVERIFY2(r.maxAbsDelta <= 1.0 + 1e-12, where.c_str());
        }
        // Both verdicts are well represented (the draw is not degenerate).
        QVERIFY(collapsed > kCases / 10 && stable > kCases / 10);
    }
    void sampleAgreesWithQuadrature() {
        // Every 500th case of the same walk whose run is short enough for the reference's fixed
        // steps (period / 64) is replayed: the same outcome, and tau_c (or the residual)
        // within 1e-8.
        std::mt19937_64 g(kSeed);
        int compared = 0;
        for (int i = 0; i < 10000 && compared < 12; ++i) {
            const RandomCase c = drawCase(g);
            if (i % 500 != 0) continue;
            const EnvelopedSine a(c.envelope, c.amplitude, c.frequency, c.tstar);
            const SlabResult exact = solve(c, a);
            const double period = 2.0 * std::numbers::pi / a.omega();
            if (exact.tauEnd / period > 3000.0) continue;
            testing::QuadratureReference ref(a, c.mu, 1.0, period / 64.0);
            const testing::ReferenceResult want = ref.run(exact.tauEnd + 10.0 * period);
            const std::string where = "case " + std::to_string(i) + " (" + c.name() + ")";
            QVERIFY2(exact.outcome == want.outcome, where.c_str());
            if (want.outcome == Outcome::Collapsed)
                QVERIFY2(std::abs(exact.tauC / want.tauC - 1.0) < 1e-8, where.c_str());
            else
                QVERIFY2(std::abs(exact.residualDelta - want.residualDelta) < 1e-8, where.c_str());
            ++compared;
        }
        QVERIFY(compared >= 10);
    }
};

QTEST_APPLESS_MAIN(TestRandomizedInvariants)
#include "tst_randomized_invariants.moc"
