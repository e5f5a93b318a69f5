// SPDX-License-Identifier: GPL-3.0-or-later
// The planar work-precision study (core/precision/PlanarPrecision.h): what the tolerance of the
// planar solver buys. Its reference (the solver at rel 1e-13) must agree with an independent
// method, Moreau's implicit Euler at h = 2e-3 and 1e-3 with Richardson extrapolation, as in
// tst_planar_reference (within 1e-6; the extrapolation's own error is O(h^2)). The default
// tolerance (rel 1e-10) must keep tau_c within 1e-8 of the reference, the accuracy the golden
// comparison (tst_planar_golden) documents, and a loose tolerance must be measurably worse. (A
// loose tolerance is not always cheaper: near |u| = 0 the explicit steps are limited by the
// direction's relaxation rate |a|/|u| and, at rel 1e-6, rejected over and over; the study shows
// it, so it is not asserted either way.)

#include "core/precision/PlanarPrecision.h"
#include "core/records/RecordReader.h"
#include "core/slab/PlanarSettings.h"

#include "RecordMotions.h"

#include <QtTest>

#include <cmath>

using namespace kinstab;

class TestPlanarPrecision : public QObject {
    Q_OBJECT
private slots:
    void toleranceBuysAccuracy();
};

void TestPlanarPrecision::toleranceBuysAccuracy() {
    PlanarPrecisionOptions o;
    o.repeats = 1;
    o.verticalUp = verticalMotion(readRecord(testing::kRecords + std::string(kRsn68UpFileName)),
                                  PlanarCase{}.common.tstar);
    const PlanarPrecisionStudy s = runPlanarPrecisionStudy(o);
    QCOMPARE(s.cases.size(), std::size_t(3));
    QCOMPARE(s.rows.size(), 3 * planarPrecisionTolerances().size());
    qInfo("reference against Moreau + Richardson: %.2e", s.referenceCheck);
    QVERIFY(s.referenceCheck < 1e-6);
    for (const WorkPrecisionRow& r : s.rows) {
        qInfo("%s %s: error %.2e, %ld evaluations", r.caseId.c_str(), r.setting.c_str(), r.error,
              r.accelEvaluations);
        QVERIFY(std::isfinite(r.error));
        if (r.parameter <= 1e-10) {
            QCOMPARE(r.outcomeMismatches, 0);
            QVERIFY2(r.error < 1e-8,
                     qPrintable(QString::fromStdString(r.caseId + " " + r.setting)));
        }
    }
    for (std::size_t c = 0; c < s.cases.size(); ++c) {
        const WorkPrecisionRow& loose = s.rows[c * planarPrecisionTolerances().size()];
        const WorkPrecisionRow& tight = s.rows[(c + 1) * planarPrecisionTolerances().size() - 1];
        QVERIFY(loose.error > 10.0 * tight.error);
    }
}

QTEST_APPLESS_MAIN(TestPlanarPrecision)
#include "tst_planar_precision.moc"
