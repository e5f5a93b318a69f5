// SPDX-License-Identifier: GPL-3.0-or-later
// The product-limit (Kaplan-Meier) empirical fragility of core/study/KaplanMeier.h:
//  - without censoring it is the plain empirical CDF, (collapses <= x) / (all records), to the
//    last bit, ties included;
//  - with records censored below some collapses it is the product written out by hand below;
//  - a record censored at a collapse intensity counts as at risk there.

#include "core/study/KaplanMeier.h"

#include <QtTest>

using namespace kinstab;

class TestKaplanMeier : public QObject {
    Q_OBJECT
private slots:
    void withoutCensoringItIsTheEmpiricalCdf() {
        // 5 records, two collapsing at 0.2 g: F = 1/5, 3/5, 4/5, 5/5.
        const auto steps = kaplanMeier({{0.3, 0.2, 0.1, 0.2, 0.45}, {}});
        QCOMPARE(steps.size(), std::size_t(4));
        const double x[] = {0.1, 0.2, 0.3, 0.45}, f[] = {1.0 / 5, 3.0 / 5, 4.0 / 5, 5.0 / 5};
        for (std::size_t i = 0; i < 4; ++i) {
            QCOMPARE(steps[i].intensity, x[i]);
            QCOMPARE(steps[i].probability, f[i]); // exact: the same double as k / n
        }
        // Censored above every collapse: still k / n of all records (3 of 7 collapse).
        const auto high = kaplanMeier({{0.5, 0.7, 0.6}, {2.0, 2.5, 2.0, 3.0}});
        QCOMPARE(high.back().probability, 3.0 / 7.0);
        QCOMPARE(high.front().probability, 1.0 / 7.0);
    }
    void censoredBelowACollapseFollowsTheProduct() {
        // Collapses at 0.2, 0.4, 0.5, 0.8 g; censored at 0.3 and 0.6 g (6 records).
        //   t = 0.2: at risk 6, 1 collapses: S = 5/6                      F = 1/6
        //   t = 0.4: at risk 4 (0.4, 0.5, 0.8; 0.6): S = 5/6 x 3/4 = 5/8  F = 3/8
        //   t = 0.5: at risk 3 (0.5, 0.8; 0.6):      S = 5/8 x 2/3 = 5/12 F = 7/12
        //   t = 0.8: at risk 1:                      S = 0                F = 1
        // (hits / total would say 2/6 at 0.4 g and 4/6 at 0.8 g.)
        const auto steps = kaplanMeier({{0.8, 0.2, 0.5, 0.4}, {0.6, 0.3}});
        QCOMPARE(steps.size(), std::size_t(4));
        QCOMPARE(steps[0].probability, 1.0 / 6.0);
        QCOMPARE_LT(std::abs(steps[1].probability - 3.0 / 8.0), 1e-15);
        QCOMPARE_LT(std::abs(steps[2].probability - 7.0 / 12.0), 1e-15);
        QCOMPARE_LT(std::abs(steps[3].probability - 1.0), 1e-15);
    }
    void aRecordCensoredAtACollapseIsAtRiskThere() {
        // Collapses 0.1, 0.4; censored 0.1: t = 0.1 at risk 3, S = 2/3; t = 0.4 at risk 1, S = 0.
        // (Counting the censored record out at 0.1 would give S = 1/2 there.)
        const auto steps = kaplanMeier({{0.1, 0.4}, {0.1}});
        QCOMPARE(steps[0].probability, 1.0 / 3.0);
        QCOMPARE_LT(std::abs(steps[1].probability - 1.0), 1e-15);
        QVERIFY(kaplanMeier({{}, {0.5}}).empty());
    }
};

QTEST_APPLESS_MAIN(TestKaplanMeier)
#include "tst_kaplan_meier.moc"
