// SPDX-License-Identifier: GPL-3.0-or-later
// SlabModel2D::segmentEnd keeps the enveloped sines' next cut while later times ask before it
// (issue 34). The reference is the definition it replaces: the least of the components' own
// segmentEnd at the same time, asked of each component every time. Times are asked in the order
// the planar run asks them (each window from the last one's end, the vertical record cutting at
// every sample) and then at and around every cut (one and two ulps, 1e-9 of a half-period either
// side, where a half-period's index steps) and backwards, so a kept cut that is stale fails.
#include "core/excitation/EnvelopedSine.h"
#include "core/excitation/RecordedMotion.h"
#include "core/slab/Slab1DCase.h"
#include "core/slab/SlabModel2D.h"

#include <QtTest>

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>
#include <vector>

using namespace kinstab;

class TestPlanarCuts : public QObject {
    Q_OBJECT
private slots:
    void keptCutIsTheComponentsCut();
};

void TestPlanarCuts::keptCutIsTheComponentsCut() {
    const Slab1DCase common;
    auto x = std::make_shared<EnvelopedSine>(common.envelope, 0.5, 0.75, common.tstar);
    auto y = std::make_shared<EnvelopedSine>(common.envelope, 0.45, 1.0, common.tstar);
    Accelerogram rec; // a short vertical record: a sample every dt / t* = 0.101 of tau
    rec.dt = 0.01;
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> sample(-0.3, 0.3);
    for (int i = 0; i < 4000; ++i)
        rec.samples.push_back(sample(rng));
    auto z = std::make_shared<RecordedMotion>(rec, common.tstar);
    const SlabModel2D m(x, y, z, PlanarParams{});
    const auto reference = [&](double t) {
        return std::min({x->segmentEnd(t), y->segmentEnd(t), z->segmentEnd(t)});
    };
    std::vector<double> times;
    for (double w0 = 0.0; w0 < 500.0 && times.size() < 20000;)
        times.push_back(w0 = reference(w0));
    const std::size_t windows = times.size();
    for (std::size_t i = 0; i < windows; ++i) {
        const double c = times[i];
        for (double d : {1e-9 * x->halfPeriod(), 1e-9 * y->halfPeriod()})
            times.insert(times.end(), {c - 2.0 * d, c - d, c - 0.5 * d, c + 0.5 * d, c + d});
        const double below = std::nextafter(c, 0.0), above = std::nextafter(c, 1e9);
        times.insert(times.end(), {below, std::nextafter(below, 0.0), above});
    }
    times.insert(times.end(), times.rbegin(), times.rend()); // and backwards
    for (double t : times)
        QVERIFY2(m.segmentEnd(t) == reference(t), qPrintable(QString::number(t, 'g', 17)));
    QVERIFY(windows > 3900); // the record's samples, cut also at the sines' half-periods
}

QTEST_APPLESS_MAIN(TestPlanarCuts)
#include "tst_planar_cuts.moc"
