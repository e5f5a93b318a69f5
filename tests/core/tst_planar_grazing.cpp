// SPDX-License-Identifier: GPL-3.0-or-later
// A slab that stays on its walls never went past an edge: for every run that ends stable, the
// largest |dx| (sampled at step ends and, inside a step, at the interpolant's extremum) is at
// most the bearing limit and |dy| at most Θ. Near A_crit the path can pass the edge inside one
// integration step and come back by the step's end; such a run must end in collapse, not stable
// (found at f_x = 1.5 Hz, f_y = 1 Hz, A between 0.83924 and 0.83947 g, where max |dx| read
// 1.00005 while the run was called stable). The grid straddles that boundary.

#include "core/slab/PlanarCase.h"

#include <QtTest>

using namespace kinstab;

class TestPlanarGrazing : public QObject {
    Q_OBJECT
private slots:
    void stableRunsStayInside() {
        PlanarCase c;
        c.fyHz = 1.0;
        const PlanarParams p = c.params();
        int stable = 0, collapsed = 0;
        for (int i = 0; i <= 12; ++i) {
            const double a = 0.8390 + 0.00005 * i;
            const PlanarResult r = runPlanar(c, a, 1.5);
            const QString where = QString("A = %1 g").arg(a, 0, 'f', 5);
            if (r.slab.outcome == Outcome::Collapsed) {
                ++collapsed;
                continue;
            }
            ++stable;
            QVERIFY2(r.slab.maxAbsDelta <= p.limit,
                     qPrintable(where + QString(": stable with max |dx| = %1 > %2")
                                            .arg(r.slab.maxAbsDelta, 0, 'g', 12)
                                            .arg(p.limit)));
            QVERIFY2(r.maxAbsDeltaY <= p.theta, qPrintable(where + ": stable past Θ"));
        }
        // The boundary lies inside the grid: both outcomes occur, collapse above.
        QVERIFY(stable > 0);
        QVERIFY(collapsed > 0);
    }
};

QTEST_APPLESS_MAIN(TestPlanarGrazing)
#include "tst_planar_grazing.moc"
