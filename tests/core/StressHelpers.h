// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Shared by the stress tests (tst_stress_*): a finite-and-bounded check for every result,
// an excitation wrapper for the a -> -a metamorphic test, and independent integrals of a(tau)
// by composite Gauss-Legendre (no closed forms).

#include "core/excitation/Excitation1D.h"
#include "core/numerics/GaussLegendre.h"
#include "core/slab/SlabTypes.h"

#include <QtTest>
#include <array>
#include <cmath>

namespace kinstab::testing {

// Every run must end with a defined outcome, finite numbers and a bounded amount of work.
// events: what a SlabEventLog kept of the run, when one was passed.
inline void checkDefined(const SlabResult& r, long maxEvents = 1'000'000,
                         const std::vector<SlabEvent>& events = {}) {
    QVERIFY2(r.outcome != Outcome::Failed, r.failure.c_str());
    QVERIFY(std::isfinite(r.tauEnd));
    QVERIFY(std::isfinite(r.residualDelta));
    QVERIFY(std::isfinite(r.maxAbsDelta));
    if (r.outcome == Outcome::Collapsed) QVERIFY(std::isfinite(r.tauC));
    QVERIFY(r.work.events <= maxEvents);
    for (const SlabEvent& e : events) {
        QVERIFY(std::isfinite(e.tau));
        QVERIFY(std::isfinite(e.delta));
        QVERIFY(std::isfinite(e.velocity));
    }
}

// a(tau) -> -a(tau): every answer must come out mirrored (docs/theory.md §6.6, metamorphic tests).
class NegatedExcitation final : public Excitation1D {
public:
    explicit NegatedExcitation(const Excitation1D& a) : a_(a) {}
    double accel(double tau) const override { return -a_.accel(tau); }
    double accelSlope(double tau) const override { return -a_.accelSlope(tau); }
    double velocityChange(double t0, double t1) const override {
        return -a_.velocityChange(t0, t1);
    }
    double displacementChange(double t0, double t1) const override {
        return -a_.displacementChange(t0, t1);
    }
    double velocityChangeAndAccel(double t0, double t1, double& accelAtT1) const override {
        const double dv = -a_.velocityChangeAndAccel(t0, t1, accelAtT1);
        accelAtT1 = -accelAtT1;
        return dv;
    }
    double velocityChangeAndSlopes(double t0, double t1, AccelAt& at) const override {
        const double dv = -a_.velocityChangeAndSlopes(t0, t1, at);
        at = {-at.a, -at.da, -at.d2a};
        return dv;
    }
    double velocityAndDisplacementChange(double t0, double t1, double& dx) const override {
        const double dv = -a_.velocityAndDisplacementChange(t0, t1, dx);
        dx = -dx;
        return dv;
    }
    // humpCrossing() is not forwarded: the mirror test then checks Excitation1D's generic one
    // (through crossings()) against EnvelopedSine's own.
    int humpSign(double lo, double hi) const override { return -a_.humpSign(lo, hi); }
    double segmentEnd(double s) const override { return a_.segmentEnd(s); }
    Crossings crossings(double level, double s0, double s1) const override {
        return a_.crossings(-level, s0, s1);
    }
    double boundAfter(double tau) const override { return a_.boundAfter(tau); }
    double boundOn(double lo, double hi) const override { return a_.boundOn(lo, hi); }
    double peak() const override { return a_.peak(); }

private:
    const Excitation1D& a_;
};

// int_0^T a and int_0^T (T - s) a(s) ds by 10-point Gauss-Legendre on n equal pieces.
struct Integrals {
    double first = 0, second = 0;
};
template <class A> Integrals integrate(A&& accel, double T, int pieces) {
    Integrals out;
    for (int p = 0; p < pieces; ++p) {
        const double lo = T * p / pieces, hi = T * (p + 1) / pieces;
        out.first += gaussLegendre10(accel, lo, hi);
        out.second += gaussLegendre10([&](double s) { return (T - s) * accel(s); }, lo, hi);
    }
    return out;
}
inline Integrals integrateAccel(const Excitation1D& a, double T, int pieces) {
    return integrate([&](double s) { return a.accel(s); }, T, pieces);
}

} // namespace kinstab::testing
