// SPDX-License-Identifier: GPL-3.0-or-later
// The planar slab driven by records (core/slab/PlanarRecordCase.h): with no motion along the
// walls and no vertical motion it is the 1-DOF slab under the same record, so its collapse time
// must agree with the event-driven 1-DOF solver (exact for the interpolated record) to 1e-8
// relative (docs/theory.md §5's check, here for records); a second component moves the slab along
// the walls, scaled by the first component's factor.

#include "core/excitation/FloorFilter.h"
#include "core/records/RecordReader.h"
#include "core/slab/PlanarRecordCase.h"
#include "core/slab/RecordRun.h"

#include "RecordMotions.h"

#include <QtTest>

#include <cmath>

using namespace kinstab;

using testing::motionOf;

class TestPlanarRecord : public QObject {
    Q_OBJECT
private slots:
    void agreesWithOneDof_data() {
        QTest::addColumn<QString>("file");
        QTest::addColumn<double>("floorPeriod");
        QTest::addColumn<double>("peak");
        // Peaks above each record's critical peak (tst_record_critical), so the slab collapses.
        QTest::newRow("El Centro 180 ground, 1.5 g") << "RSN6_IMPVALL.I_I-ELC180.AT2" << 0.0 << 1.5;
        QTest::newRow("El Centro 180 ground, 2.5 g") << "RSN6_IMPVALL.I_I-ELC180.AT2" << 0.0 << 2.5;
        QTest::newRow("Pacoima Dam 164 floor T 1 s, 1.2 g")
            << "RSN77_SFERN_PUL164.AT2" << 1.0 << 1.2;
        QTest::newRow("Pacoima Dam 164 ground, 0.9 g (stable)")
            << "RSN77_SFERN_PUL164.AT2" << 0.0 << 0.9;
    }
    void agreesWithOneDof() {
        QFETCH(QString, file);
        QFETCH(double, floorPeriod);
        QFETCH(double, peak);
        const Accelerogram m = motionOf(file.toStdString(), floorPeriod);
        const Slab1DCase one;
        const SlabResult a = runRecord1D(one, m, peak);
        PlanarCase c;
        const PlanarResult b = runPlanarRecord(c, PlanarRecordMotions{m, std::nullopt, peak});
        QCOMPARE(outcomeName(b.slab.outcome), outcomeName(a.outcome));
        QCOMPARE(b.slab.slipIntervals, a.slipIntervals);
        QCOMPARE(b.maxAbsDeltaY, 0.0);
        if (a.outcome == Outcome::Collapsed) {
            qInfo("tau_c 1-DOF %.12g planar %.12g", a.tauC, b.slab.tauC);
            QCOMPARE_LE(std::abs(b.slab.tauC - a.tauC), 1e-8 * a.tauC);
        } else {
            QCOMPARE_LE(std::abs(b.slab.maxAbsDelta - a.maxAbsDelta), 1e-7);
        }
    }
    void secondComponentScaledByTheSameFactor() {
        const Accelerogram x = motionOf("RSN68_SFERN_PEL090.AT2", 0.0);
        const Accelerogram y = motionOf("RSN68_SFERN_PEL180.AT2", 0.0);
        const PlanarCase c;
        const double peak = 0.9;
        const SlabModel2D model = planarRecordModel(c, PlanarRecordMotions{x, y, peak});
        QVERIFY(model.hasAlongWalls());
        // At y's own peak sample a_y is y's peak times x's factor.
        const double factor = peak / std::abs(x.peak().value);
        const SignedPeak py = y.peak();
        const double tauY = py.time / c.common.tstar;
        QCOMPARE_LE(std::abs(model.accel(tauY).y - factor * py.value), 1e-12);
        const PlanarResult r = solvePlanar(model, c.solver);
        QCOMPARE_GT(r.maxAbsDeltaY, 0.0);
    }
    void badMotionsAreNamed() {
        Accelerogram flat;
        flat.dt = 0.01;
        flat.samples = {0.0, 0.0, 0.0};
        const QString e = QString::fromStdString(
            validatePlanarRecordMotions(PlanarRecordMotions{flat, std::nullopt, 0.5}, 0.099));
        QVERIFY2(e.startsWith("x record: "), qPrintable(e));
        const Accelerogram x = motionOf("RSN6_IMPVALL.I_I-ELC180.AT2", 0.0);
        Accelerogram bad = x;
        bad.dt = -1;
        QVERIFY(QString::fromStdString(
                    validatePlanarRecordMotions(PlanarRecordMotions{x, bad, 0.5}, 0.099))
                    .startsWith("y record: "));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                                 planarRecordModel(PlanarCase{}, {flat, std::nullopt, 0.5}));
    }
};

QTEST_APPLESS_MAIN(TestPlanarRecord)
#include "tst_planar_record.moc"
