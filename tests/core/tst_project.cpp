// SPDX-License-Identifier: GPL-3.0-or-later
// The project file: round trip of every field, the shipped example, and broken files.

#include "core/io/Project.h"

#include <QtTest>

#include <filesystem>
#include <fstream>

using namespace kinstab;

namespace {

// A project where every field differs from its default, so a field that save or load drops
// shows up.
Project everyField() {
    Project p;
    p.name = "every field";
    p.description = "round trip \"quoted\" ünïcode";
    Building& b = p.building;
    b.name = "B";
    b.stories = 3;
    b.unit = LengthUnit::Metres;
    b.height = 10.5;
    b.planDimension = 12.25;
    b.period = 0.37;
    b.system = StructuralSystem::SteelBracedEccentric;
    b.occupancy = Occupancy::Hazardous;
    b.storyWeights = {3.0, 2.0, 1.0};
    b.storyHeights = {4.0, 3.25, 3.25};
    p.codes.ubc1976 = Ubc1976Inputs{2, 1.25, 1.33, 0.9};
    p.codes.atc306 = Atc306Inputs{6, 0.3, 0.3, AtcSoil::S2, 4.5};
    p.codes.ubc1997 = Ubc1997Inputs{Ubc97Zone::Z4, Ubc97Soil::SE, 1.2, 1.6, 1.25, 5.5};
    p.codes.asce7_22 = Asce7Inputs{1.1, 0.7, 0.65, 12.0, "CD", 3, 1.25, 7.0};
    p.codes.ec8 = Eurocode8Inputs{Ec8Ground::E, 2, 0.3, 3, 1.15, 3.3, 0.15, false};
    p.slab.envelope = Envelope{0.2, 0.9, std::nullopt};
    p.wallWidthIn = 11.625;
    p.slab.tstar = tstarFromWallWidthInches(11.625);
    p.slab.slab.mu = 0.45;
    p.slab.slab.limit = 1.5;
    p.slab.slab.duration = 400.0;
    p.slab.solver = SolverKind::Paper;
    p.slab.paperStepsPerPeriod = 64;
    p.slab.scale = TauScale::TauRise;
    p.grid.amplitudes = {0.6, 0.8};
    p.grid.frequencies = {0.25, 3.0, 7.5};
    p.model = ModelKind::Planar;
    p.critical = CriticalSearch{0.5, 3.0, 0.02, 1e-5};
    return p;
}

std::string tempPath(const char* name) {
    return (std::filesystem::temp_directory_path() /
            ("kinstab_tst_project_" + std::to_string(::getpid()) + name))
        .string();
}

void writeText(const std::string& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
}

} // namespace

class TestProject : public QObject {
    Q_OBJECT
private slots:
    void roundTripEveryField() {
        const Project a = everyField();
        QCOMPARE(QString::fromStdString(validateProject(a)), QString());
        const std::string path = tempPath("rt.json");
        saveProject(a, path);
        const Project b = loadProject(path);
        std::filesystem::remove(path);
        QCOMPARE(b.name, a.name);
        QCOMPARE(b.description, a.description);
        QCOMPARE(b.building.name, a.building.name);
        QCOMPARE(b.building.stories, a.building.stories);
        QVERIFY(b.building.unit == a.building.unit);
        QCOMPARE(b.building.height, a.building.height);
        QCOMPARE(b.building.planDimension, a.building.planDimension);
        QCOMPARE(b.building.period, a.building.period);
        QVERIFY(b.building.system == a.building.system);
        QVERIFY(b.building.occupancy == a.building.occupancy);
        QCOMPARE(b.building.storyWeights, a.building.storyWeights);
        QCOMPARE(b.building.storyHeights, a.building.storyHeights);
        QVERIFY(b.codes.ubc1976 && b.codes.atc306 && b.codes.ubc1997 && b.codes.asce7_22 &&
                b.codes.ec8);
        QCOMPARE(b.codes.ubc1976->zone, 2);
        QCOMPARE(b.codes.ubc1976->importance, std::optional<double>(1.25));
        QCOMPARE(b.codes.ubc1976->k, 1.33);
        QCOMPARE(b.codes.ubc1976->sitePeriod, std::optional<double>(0.9));
        QCOMPARE(b.codes.atc306->mapArea, std::optional<int>(6));
        QCOMPARE(b.codes.atc306->aa, 0.3);
        QCOMPARE(b.codes.atc306->av, 0.3);
        QVERIFY(b.codes.atc306->soil == AtcSoil::S2);
        QCOMPARE(b.codes.atc306->r, 4.5);
        QVERIFY(b.codes.ubc1997->zone == Ubc97Zone::Z4);
        QVERIFY(b.codes.ubc1997->soil == Ubc97Soil::SE);
        QCOMPARE(b.codes.ubc1997->na, 1.2);
        QCOMPARE(b.codes.ubc1997->nv, 1.6);
        QCOMPARE(b.codes.ubc1997->importance, std::optional<double>(1.25));
        QCOMPARE(b.codes.ubc1997->r, 5.5);
        QCOMPARE(b.codes.asce7_22->sds, 1.1);
        QCOMPARE(b.codes.asce7_22->sd1, 0.7);
        QCOMPARE(b.codes.asce7_22->s1, std::optional<double>(0.65));
        QCOMPARE(b.codes.asce7_22->tl, 12.0);
        QCOMPARE(b.codes.asce7_22->siteClass, std::string("CD"));
        QCOMPARE(b.codes.asce7_22->riskCategory, std::optional<int>(3));
        QCOMPARE(b.codes.asce7_22->importance, std::optional<double>(1.25));
        QCOMPARE(b.codes.asce7_22->r, 7.0);
        QVERIFY(b.codes.ec8->ground == Ec8Ground::E);
        QCOMPARE(b.codes.ec8->spectrumType, 2);
        QCOMPARE(b.codes.ec8->agr, 0.3);
        QCOMPARE(b.codes.ec8->importanceClass, std::optional<int>(3));
        QCOMPARE(b.codes.ec8->gammaI, std::optional<double>(1.15));
        QCOMPARE(b.codes.ec8->q, 3.3);
        QCOMPARE(b.codes.ec8->beta, 0.15);
        QCOMPARE(b.codes.ec8->regularInElevation, false);
        QCOMPARE(b.slab.envelope.alpha, 0.2);
        QCOMPARE(b.slab.envelope.beta, 0.9);
        QVERIFY(!b.slab.envelope.preset);
        QCOMPARE(b.wallWidthIn, a.wallWidthIn);
        QCOMPARE(b.slab.tstar, a.slab.tstar);
        QCOMPARE(b.slab.slab.mu, 0.45);
        QCOMPARE(b.slab.slab.limit, 1.5);
        QCOMPARE(b.slab.slab.duration, std::optional<double>(400.0));
        QVERIFY(b.slab.solver == SolverKind::Paper);
        QCOMPARE(b.slab.paperStepsPerPeriod, 64.0);
        QVERIFY(b.slab.scale == TauScale::TauRise);
        QCOMPARE(b.grid.amplitudes, a.grid.amplitudes);
        QCOMPARE(b.grid.frequencies, a.grid.frequencies);
        QVERIFY(b.model == ModelKind::Planar);
        QCOMPARE(b.critical.from, 0.5);
        QCOMPARE(b.critical.to, 3.0);
        QCOMPARE(b.critical.scanStep, 0.02);
        QCOMPARE(b.critical.tolerance, 1e-5);
        // And the JSON is a fixed point.
        QCOMPARE(projectToJson(b).dump(), projectToJson(a).dump());
    }
    void roundTripDefaultsAndPresets() {
        const Project a = paperExampleProject();
        const Project b = parseProject(projectToJson(a).dump());
        QCOMPARE(projectToJson(b).dump(), projectToJson(a).dump());
        QVERIFY(b.slab.envelope.preset == EnvelopePreset::Moderate);
        QVERIFY(!b.codes.ubc1997);
        QVERIFY(!b.wallWidthIn);
    }
    void shippedExampleIsThePaperBuilding() {
        // resources/examples/paper-16-story.json is what paperExampleProject() builds, plus
        // example title-block metadata (engineer, client, revisions) for the report.
        Project p = loadProject(KINSTAB_SOURCE_DIR "/resources/examples/paper-16-story.json");
        QVERIFY(!p.info.empty());
        p.info = {};
        QCOMPARE(projectToJson(p).dump(), projectToJson(paperExampleProject()).dump());
        QCOMPARE(p.grid.amplitudes.size(), std::size_t(10)); // 0.70:1.15:0.05
        QCOMPARE(p.grid.frequencies.size(), std::size_t(6)); // 0.5:1.125:0.125
        QCOMPARE(p.building.stories, 16);
        QCOMPARE(p.building.height, 177.0);
        QCOMPARE(p.building.planDimension, 78.62);
    }
    void brokenFiles_data() {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("mention");
        const std::string good = projectToJson(paperExampleProject()).dump(2);
        QTest::newRow("truncated")
            << QString::fromStdString(good.substr(0, good.size() / 2)) << "truncated or corrupt";
        QTest::newRow("empty") << ""
                               << "not valid JSON";
        QTest::newRow("binary garbage") << QString("\x01\x02PK\x03") << "not valid JSON";
        QTest::newRow("array") << "[1,2]"
                               << "expected an object";
        QTest::newRow("other format") << R"({"format":"x","version":1})"
                                      << "format";
        QTest::newRow("future version") << R"({"format":"kinstab-project","version":7})"
                                        << "version";
        QTest::newRow("no building") << R"({"format":"kinstab-project","version":1})"
                                     << "building: missing";
        QTest::newRow("height text")
            << R"({"format":"kinstab-project","version":1,"building":{"height":"tall","plan_dimension":10}})"
            << "building.height: expected a number";
        QTest::newRow("negative height")
            << R"({"format":"kinstab-project","version":1,"building":{"height":-3,"plan_dimension":10}})"
            << "building.height = -3";
        QTest::newRow("zone 7")
            << R"({"format":"kinstab-project","version":1,"building":{"height":30,"plan_dimension":10},"codes":{"ubc1976":{"zone":7,"k":1}}})"
            << "ubc1976.zone = 7";
        QTest::newRow("bad unit")
            << R"({"format":"kinstab-project","version":1,"building":{"unit":"yd","height":30,"plan_dimension":10}})"
            << "building.unit";
        QTest::newRow("mu negative")
            << R"({"format":"kinstab-project","version":1,"building":{"height":30,"plan_dimension":10},"slab":{"envelope":"moderate","mu":-1}})"
            << "mu";
        QTest::newRow("grid entry")
            << R"({"format":"kinstab-project","version":1,"building":{"height":30,"plan_dimension":10},"grid":{"amplitudes":[1,"x"],"frequencies":[1]}})"
            << "grid.amplitudes";
    }
    void brokenFiles() {
        QFETCH(QString, text);
        QFETCH(QString, mention);
        const std::string path = tempPath("broken.json");
        writeText(path, text.toStdString());
        QString message;
        try {
            loadProject(path);
        } catch (const ProjectError& e) {
            message = QString::fromUtf8(e.what());
        }
        std::filesystem::remove(path);
        QVERIFY2(message.contains(mention), qPrintable(message));
        QVERIFY2(message.startsWith(QString::fromStdString(path)), qPrintable(message));
    }
    void missingFileAndDirectory() {
        QVERIFY_THROWS_EXCEPTION(ProjectError, loadProject("/nonexistent/dir/p.json"));
        QVERIFY_THROWS_EXCEPTION(ProjectError,
                                 loadProject(std::filesystem::temp_directory_path().string()));
    }
    void saveIsAtomicAndRefusesBadProjects() {
        const std::string path = tempPath("atomic.json");
        saveProject(paperExampleProject(), path);
        Project bad = paperExampleProject();
        bad.building.height = -1;
        QVERIFY_THROWS_EXCEPTION(ProjectError, saveProject(bad, path));
        QVERIFY_THROWS_EXCEPTION(ProjectError,
                                 saveProject(paperExampleProject(), "/nonexistent/dir/p.json"));
        // The earlier file is intact and nothing else was left in the directory.
        QCOMPARE(loadProject(path).building.height, 177.0);
        int leftovers = 0;
        for (const auto& e :
             std::filesystem::directory_iterator(std::filesystem::temp_directory_path()))
            if (e.path().string().rfind(path + ".tmp", 0) == 0) ++leftovers;
        QCOMPARE(leftovers, 0);
        std::filesystem::remove(path);
    }
};

QTEST_APPLESS_MAIN(TestProject)
#include "tst_project.moc"
