// SPDX-License-Identifier: GPL-3.0-or-later
// The GUI's block model as the project keeps it ("block_map", core/io/BlockMapJson.h) and the
// recorded path the Teaching tab animates (core/rocking/RockingPath.h): a round trip keeps every
// field; absent keys take their defaults and a file without the key is the slab model; a bad
// value names its field; the map's spec steps from max/points; the path is read between the
// solver's samples (values worked by hand below) and an overturning path ends lying down.

#include "core/io/Project.h"
#include "core/rocking/Pulse.h"
#include "core/rocking/RockingPath.h"

#include <QtTest>

#include <cmath>
#include <numbers>

using namespace kinstab;

class TestBlockMapSettings : public QObject {
    Q_OBJECT
private slots:
    void roundTripKeepsEveryField() {
        Project p = paperExampleProject();
        p.blockMap.selected = true;
        p.blockMap.block = {0.25, 0.75};
        p.blockMap.mu = 0.7;
        p.blockMap.restitution = 0.85;
        p.blockMap.equations = RockingEquations::Linearised;
        p.blockMap.shape = PulseShape::Rectangular;
        p.blockMap.amplitudeMax = 6.0;
        p.blockMap.frequencyMax = 8.0;
        p.blockMap.points = 33;
        const Project q = parseProject(projectText(p));
        QVERIFY(q.blockMap == p.blockMap);
        const nlohmann::json j = projectToJson(p)["block_map"];
        QCOMPARE(j["half_width_m"].get<double>(), 0.25);
        QCOMPARE(j["equations"].get<std::string>(), std::string("linearised"));
        QCOMPARE(j["pulse"].get<std::string>(), std::string("rectangular"));
    }
    void absentMeansTheSlab() {
        const Project p = paperExampleProject();
        QVERIFY(!projectToJson(p).contains("block_map")); // old files save without it
        nlohmann::json j = projectToJson(p);
        j["block_map"] = nlohmann::json::object({{"selected", true}});
        const Project q = projectFromJson(j);
        BlockMapSettings defaults;
        defaults.selected = true;
        QVERIFY(q.blockMap == defaults);
    }
    void badValueNamesItsField_data() {
        QTest::addColumn<QString>("key");
        QTest::addColumn<QString>("value");
        QTest::newRow("b") << "half_width_m"
                           << "-1";
        QTest::newRow("h") << "half_height_m"
                           << "0";
        QTest::newRow("mu") << "mu"
                            << "0";
        QTest::newRow("restitution") << "restitution"
                                     << "1.5";
        QTest::newRow("points") << "points"
                                << "1";
        QTest::newRow("points fraction") << "points"
                                         << "10.5";
        QTest::newRow("equations") << "equations"
                                   << "\"nonlinear\"";
        QTest::newRow("pulse") << "pulse"
                               << "\"triangle\"";
    }
    void badValueNamesItsField() {
        QFETCH(QString, key);
        QFETCH(QString, value);
        nlohmann::json j = projectToJson(paperExampleProject());
        j["block_map"] = nlohmann::json::object();
        j["block_map"][key.toStdString()] = nlohmann::json::parse(value.toStdString());
        try {
            projectFromJson(j);
            QFAIL("accepted");
        } catch (const ProjectError& e) {
            QVERIFY2(QString(e.what()).contains("block_map." + key), e.what());
        }
    }
    void specStepsFromMaxOverPoints() {
        BlockMapSettings s;
        s.amplitudeMax = 9.0;
        s.frequencyMax = 4.0;
        s.points = 9;
        const OverturningMapSpec spec = blockMapSpec(s);
        QCOMPARE(spec.amplitudeMin, 1.0); // 9 / 9
        QCOMPARE(spec.frequencyMin, 4.0 / 9.0);
        QCOMPARE(spec.amplitudePoints, 9);
        QCOMPARE(otherEquationsModel(s).equations, RockingEquations::Linearised);
    }
    void pathIsReadBetweenSamples() {
        // Samples at 0, 1 (an event: two samples at t = 1) and 3; by hand:
        // t = 0.5: halfway 0 -> 0.2 = 0.1; t = 2: from the later t = 1 sample (0) halfway to -0.4
        // = -0.2; before 0 and after 3 the end samples.
        const std::vector<RockingSample> s{{0.0, 0.0, 0.0, 0.0, BlockMode::Rest},
                                           {1.0, 0.2, 1.0, 0.0, BlockMode::Rock},
                                           {1.0, 0.0, -1.0, 0.0, BlockMode::Rock},
                                           {3.0, -0.4, 0.0, 0.02, BlockMode::SlideRock}};
        QCOMPARE(pathAt(s, 0.5).theta, 0.1);
        QCOMPARE(pathAt(s, 1.0).omega, -1.0);
        QCOMPARE(pathAt(s, 2.0).theta, -0.2);
        QCOMPARE(pathAt(s, 2.0).sliding, 0.01);
        QCOMPARE(pathAt(s, 2.0).mode, BlockMode::Rock);
        QCOMPARE(pathAt(s, -1.0).theta, 0.0);
        QCOMPARE(pathAt(s, 9.0).theta, -0.4);
    }
    void overturningPathEndsLyingDown() {
        // Makris & Roussos 2000 worked example: b = 0.2 m, h = 0.6 m, linearised, a half-sine of
        // 1 Hz and 5.44 m/s^2 overturns (eq. 27: 5.4391 m/s^2).
        RockingModel m;
        m.block = {0.2, 0.6};
        m.equations = RockingEquations::Linearised;
        Pulse pulse;
        pulse.shape = PulseShape::HalfSine;
        pulse.frequencyHz = 1.0;
        pulse.amplitude = -5.44 / 9.80665;
        const RockingPath path = recordRocking(m, PulseMotion(pulse), 0.01);
        QCOMPARE(path.result.outcome, RockingOutcome::Overturns);
        QCOMPARE(path.samples.back().t, *path.result.overturnTime);
        QCOMPARE(std::abs(path.samples.back().theta), std::numbers::pi / 2);
        for (std::size_t k = 1; k < path.samples.size(); ++k)
            QVERIFY(path.samples[k].t >= path.samples[k - 1].t);
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, recordRocking(m, PulseMotion(pulse), 0.0));
    }
};

QTEST_GUILESS_MAIN(TestBlockMapSettings)
#include "tst_block_map_settings.moc"
