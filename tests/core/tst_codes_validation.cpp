// SPDX-License-Identifier: GPL-3.0-or-later
// Bad input is refused with a message naming the field, the value and the allowed range;
// nothing is computed from it (docs/theory.md §9, issue #3).

#include "core/check/DesignCheck.h"
#include "core/codes/CodeSet.h"

#include <QtTest>

#include <functional>
#include <limits>

using namespace kinstab;

Q_DECLARE_METATYPE(std::function<void()>)

namespace {
const double kNaN = std::numeric_limits<double>::quiet_NaN();

std::function<void()> withBuilding(std::function<void(Building&)> edit) {
    return [edit] {
        Building b;
        edit(b);
        runCodes(b, CodeSelection{Ubc1976Inputs{}, Atc306Inputs{}, std::nullopt, std::nullopt,
                                  std::nullopt});
    };
}
template <class In, class F>
std::function<void()> withInputs(F run, std::function<void(In&)> edit) {
    return [run, edit] {
        In in;
        edit(in);
        Building b;
        b.period = 1.0;
        run(b, in);
    };
}
} // namespace

class TestCodesValidation : public QObject {
    Q_OBJECT
private slots:
    void refused_data() {
        QTest::addColumn<std::function<void()>>("call");
        QTest::addColumn<QString>("message");
        using U = Ubc1976Inputs;
        QTest::newRow("UBC zone 5") << withInputs<U>(ubc1976, [](U& i) { i.zone = 5; })
                                    << "ubc1976.zone = 5: must be 0, 1, 2, 3 or 4";
        QTest::newRow("UBC zone 7") << withInputs<U>(ubc1976, [](U& i) { i.zone = 7; })
                                    << "ubc1976.zone = 7: must be 0, 1, 2, 3 or 4";
        QTest::newRow("UBC zone -1")
            << withInputs<U>(ubc1976, [](U& i) { i.zone = -1; }) << "ubc1976.zone = -1";
        QTest::newRow("UBC K NaN") << withInputs<U>(ubc1976, [](U& i) { i.k = kNaN; })
                                   << "ubc1976.k = nan: must be between 0.67 and 2.5";
        QTest::newRow("UBC importance 3") << withInputs<U>(ubc1976, [](U& i) { i.importance = 3; })
                                          << "ubc1976.importance = 3: must be between 1 and 1.5";
        QTest::newRow("UBC site period 0") << withInputs<U>(ubc1976, [](U& i) { i.sitePeriod = 0; })
                                           << "ubc1976.site_period_s = 0 s: must be > 0";
        using A = Atc306Inputs;
        QTest::newRow("ATC R = 0") << withInputs<A>(atc306, [](A& i) { i.r = 0; })
                                   << "atc306.r = 0: must be between 1 and 10";
        QTest::newRow("ATC Av NaN")
            << withInputs<A>(atc306, [](A& i) { i.av = kNaN; }) << "atc306.av = nan g";
        QTest::newRow("ATC map area 8") << withInputs<A>(atc306, [](A& i) { i.mapArea = 8; })
                                        << "atc306.map_area = 8: must be between 1 and 7";
        using V = Ubc1997Inputs;
        QTest::newRow("UBC97 R = 0")
            << withInputs<V>(ubc1997, [](V& i) { i.r = 0; }) << "ubc1997.r = 0";
        QTest::newRow("UBC97 Nv outside zone 4") << withInputs<V>(ubc1997, [](V& i) {
            i.zone = Ubc97Zone::Z3;
            i.nv = 1.2;
        }) << "zone 4 only";
        using S = Asce7Inputs;
        QTest::newRow("ASCE R = 0")
            << withInputs<S>(asce7_22, [](S& i) { i.r = 0; }) << "asce7_22.r = 0";
        QTest::newRow("ASCE SDS negative") << withInputs<S>(asce7_22, [](S& i) { i.sds = -1; })
                                           << "asce7_22.sds = -1 g: must be > 0";
        QTest::newRow("ASCE risk category 5")
            << withInputs<S>(asce7_22, [](S& i) { i.riskCategory = 5; })
            << "asce7_22.risk_category = 5";
        QTest::newRow("ASCE site class F")
            << withInputs<S>(asce7_22, [](S& i) { i.siteClass = "F"; }) << "site response";
        QTest::newRow("ASCE site class X")
            << withInputs<S>(asce7_22, [](S& i) { i.siteClass = "X"; })
            << "asce7_22.site_class = 'X'";
        using E = Eurocode8Inputs;
        QTest::newRow("EC8 q = 0") << withInputs<E>(eurocode8, [](E& i) { i.q = 0; })
                                   << "ec8.q = 0: must be between 1 and 8";
        QTest::newRow("EC8 spectrum type 3")
            << withInputs<E>(eurocode8, [](E& i) { i.spectrumType = 3; })
            << "ec8.spectrum_type = 3";
        QTest::newRow("negative height") << withBuilding([](Building& b) { b.height = -177; })
                                         << "building.height = -177 ft: must be > 0";
        QTest::newRow("NaN height")
            << withBuilding([](Building& b) { b.height = kNaN; }) << "building.height = nan";
        QTest::newRow("T = 0") << withBuilding([](Building& b) { b.period = 0.0; })
                               << "building.period_s = 0 s: must be between 0.02 and 20";
        // Below the stiffest buildings' 0.05 s (core/codes/Building.h, kMinPeriodS).
        QTest::newRow("T = 0.019") << withBuilding([](Building& b) { b.period = 0.019; })
                                   << "building.period_s = 0.019 s: must be between 0.02 and 20";
        QTest::newRow("T NaN") << withBuilding([](Building& b) { b.period = kNaN; })
                               << "building.period_s = nan";
        QTest::newRow("D = 0") << withBuilding([](Building& b) { b.planDimension = 0; })
                               << "building.plan_dimension = 0 ft";
        QTest::newRow("0 stories") << withBuilding([](Building& b) { b.stories = 0; })
                                   << "building.stories = 0: must be between 1 and 300";
        QTest::newRow("weights count") << withBuilding([](Building& b) {
            b.storyWeights = {1, 2};
        }) << "building.story_weights has 2 entries";
        QTest::newRow("weight negative") << withBuilding([](Building& b) {
            b.stories = 2;
            b.storyWeights = {1, -2};
        }) << "building.story_weights[1] = -2";
        QTest::newRow("heights do not sum") << withBuilding([](Building& b) {
            b.stories = 2;
            b.storyHeights = {10, 10};
        }) << "building.story_heights sum to 20 ft";
        QTest::newRow("check tolerance 0") << std::function<void()>([] {
            CriticalSearch s;
            s.tolerance = 0;
            designCheck({}, Slab1DCase{}, s);
        }) << "check.tolerance = 0";
        QTest::newRow("check mu NaN") << std::function<void()>([] {
            Slab1DCase c;
            c.slab.mu = kNaN;
            designCheck({}, c);
        }) << "mu";
    }
    void refused() {
        QFETCH(std::function<void()>, call);
        QFETCH(QString, message);
        QString got;
        try {
            call();
        } catch (const InputError& e) {
            got = QString::fromUtf8(e.what());
        }
        QVERIFY2(got.contains(message), qPrintable("got: '" + got + "'"));
    }
    void zoneZeroIsNoRequirement() {
        // docs/codes.md §2.2: zone 0 has no seismic force requirement: V = 0, ratio 0.
        Ubc1976Inputs in;
        in.zone = 0;
        const CodeResult r = ubc1976(Building{}, in);
        QCOMPARE(r.baseShearCoefficient, 0.0);
        QCOMPARE(r.topRatio, 0.0);
    }
};

QTEST_APPLESS_MAIN(TestCodesValidation)
#include "tst_codes_validation.moc"
