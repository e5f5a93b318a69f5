// SPDX-License-Identifier: GPL-3.0-or-later
// The critical PGA per level: the record search driven by each level's motion against a
// brute-force scan that scales the ground record itself (step 0.005 g of PGA), recomputes
// every floor motion from the scaled ground and runs the slab until it first collapses. The
// first collapsing PGA of the scan must lie within one step above the searched critical PGA.
// Also: the analysis ties the verdicts to the slab's level.

#include "core/assessment/RunAssessment.h"
#include "core/building/FloorAnalysis.h"
#include "core/io/Project.h"
#include "core/records/RecordReader.h"
#include "core/slab/RecordRun.h"

#include <QtTest>

#include <cmath>

using namespace kinstab;

namespace {

// The first 6 s of the Pacoima Dam 164 record (NGA RSN77): its main pulses.
Accelerogram groundRecord() {
    Accelerogram a = readRecord(KINSTAB_SOURCE_DIR "/resources/records/RSN77_SFERN_PUL164.AT2");
    a.samples.resize(static_cast<std::size_t>(6.0 / a.dt) + 1);
    return a;
}

Building threeStoreys() {
    Building b;
    b.stories = 3;
    b.height = 36.0;
    b.period = 0.4;
    return b;
}

} // namespace

class TestFloorsCritical : public QObject {
    Q_OBJECT
private slots:
    void searchMatchesBruteForceScan();
    void analysisVerdictsAtTheSlabLevel();
    void badInputNamesTheField();
    void projectSettingsRoundTrip();
};

void TestFloorsCritical::searchMatchesBruteForceScan() {
    const Accelerogram ground = groundRecord();
    const double pga = std::abs(ground.peak().value);
    const ModalModel model = modalModel(shearBuilding(threeStoreys(), StiffnessProfile::Uniform));
    const FloorMotionOptions options{0.05, 2.0};
    const Slab1DCase slab; // the paper's slab: moderate envelope, t* = 0.099 s
    CriticalSearch search;
    search.to = 3.0;
    const auto levels = levelCriticalPga(slab, floorMotions(model, ground, options), pga, search);
    QCOMPARE(levels.size(), std::size_t(3));
    const double step = 0.005;
    for (const LevelCritical& l : levels) {
        QVERIFY(l.criticalPga);
        std::optional<double> first;
        for (int k = 1; k * step <= 3.0 && !first; ++k) {
            Accelerogram scaled = ground;
            for (double& x : scaled.samples)
                x *= k * step / pga;
            const Accelerogram motion =
                floorMotions(model, scaled, options)[static_cast<std::size_t>(l.level - 1)];
            const double peak = std::abs(motion.peak().value);
            if (runRecord1D(slab, motion, peak).outcome == Outcome::Collapsed) first = k * step;
        }
        QVERIFY(first);
        qInfo("level %d: searched critical PGA %.6f g, scan's first collapse %.3f g", l.level,
              *l.criticalPga, *first);
        QVERIFY2(*first >= *l.criticalPga - 1e-6 && *first < *l.criticalPga + step + 1e-6,
                 qPrintable(QString("level %1: scan %2, search %3")
                                .arg(l.level)
                                .arg(*first)
                                .arg(*l.criticalPga)));
    }
}

void TestFloorsCritical::analysisVerdictsAtTheSlabLevel() {
    FloorAnalysisInput in;
    in.building = threeStoreys();
    in.codes.asce7_22 = Asce7Inputs{};
    in.codes.ec8 = Eurocode8Inputs{};
    in.settings.slabLevel = 2;
    in.ground = groundRecord();
    in.search.to = 3.0;
    const FloorAnalysis a = analyseFloors(in);
    QCOMPARE(a.slabLevel, 2);
    QCOMPARE(a.demands.size(), std::size_t(3));
    QCOMPARE(a.critical.size(), std::size_t(3));
    // The assessment's floor checks (core/assessment) compare at the slab's level: the code's
    // PFA there against the level's critical floor peak, and the code level's ground motion
    // against the level's critical PGA.
    Project p;
    p.building = in.building;
    p.codes = in.codes;
    p.floors = in.settings;
    AssessmentParts parts;
    parts.floors = floorCheckParts(a, in.building.stories);
    QVERIFY(parts.floors);
    QCOMPARE(parts.floors->atSlab.level, 2);
    const Assessment checks = composeAssessment(p, parts);
    QCOMPARE(checks.checks.size(), std::size_t(3));
    for (std::size_t i = 0; i < 3; ++i) {
        QCOMPARE(a.demands[i].slabLevel, 2);
        const Check& c = checks.checks[i];
        QCOMPARE(c.comparisons[0].demand, a.demands[i].groundPga);
        QCOMPARE(c.comparisons[0].capacity, a.critical[1].criticalPga);
        QCOMPARE(c.comparisons[1].demand, a.demands[i].pfa[1]);
        QCOMPARE(c.comparisons[1].capacity, a.critical[1].criticalFloorPeak);
        QCOMPARE(c.holds, c.comparisons[0].holds() && c.comparisons[1].holds());
    }
    // The SDOF filter at T and the model's roof both respond to the same record.
    QVERIFY(a.sdofRoofPeak > 0.0 && a.pfa.back() > 0.0);
}

void TestFloorsCritical::badInputNamesTheField() {
    FloorAnalysisInput in;
    in.building = threeStoreys();
    in.ground = groundRecord();
    in.settings.slabLevel = 4;
    QVERIFY(validateFloorAnalysis(in).find("floors.slab_level = 4") != std::string::npos);
    in.settings.slabLevel.reset();
    in.settings.damping = 1.5;
    QVERIFY(validateFloorAnalysis(in).find("floors.damping = 1.5") != std::string::npos);
    in.settings.damping = 0.05;
    in.ground.samples.assign(in.ground.size(), 0.0);
    QVERIFY(validateFloorAnalysis(in).find("record: all samples are zero") != std::string::npos);
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, analyseFloors(in));
}

void TestFloorsCritical::projectSettingsRoundTrip() {
    Project p = paperExampleProject();
    QVERIFY(projectToJson(p)["floors"].is_null()); // absent stays absent
    QVERIFY(!projectFromJson(projectToJson(p)).floors);
    p.floors = FloorSettings{7, StiffnessProfile::Weight, 0.03, 2.0, 0.2};
    const Project back = projectFromJson(projectToJson(p));
    QVERIFY(back.floors);
    QCOMPARE(*back.floors->slabLevel, 7);
    QCOMPARE(back.floors->stiffness, StiffnessProfile::Weight);
    QCOMPARE(back.floors->damping, 0.03);
    QCOMPARE(back.floors->omega0, 2.0);
    QCOMPARE(*back.floors->ec8ElementPeriod, 0.2);
    nlohmann::json j = projectToJson(p);
    j["floors"]["stiffness"] = "soft";
    try {
        projectFromJson(j);
        QFAIL("stiffness 'soft' was accepted");
    } catch (const ProjectError& e) {
        QVERIFY(QString(e.what()).contains("floors.stiffness"));
    }
    j["floors"]["stiffness"] = "uniform";
    j["floors"]["slab_level"] = 20;
    try {
        projectFromJson(j);
        QFAIL("slab level 20 of 16 was accepted");
    } catch (const ProjectError& e) {
        QVERIFY(QString(e.what()).contains("floors.slab_level = 20"));
    }
}

QTEST_APPLESS_MAIN(TestFloorsCritical)
#include "tst_floors_critical.moc"
