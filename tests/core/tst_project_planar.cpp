// SPDX-License-Identifier: GPL-3.0-or-later
// The planar settings in the project file (docs/user-guide.md, core/io/PlanarJson.h): round trip,
// old projects without the key, and a message naming each bad field and its value.

#include "core/io/Project.h"

#include <QDir>
#include <QTemporaryDir>
#include <QtTest>

#include <fstream>

using namespace kinstab;
using nlohmann::json;

namespace {

// The shipped paper project written as JSON, with `planar` replaced (or removed when null).
json paperJsonWithPlanar(const json& planar) {
    json j = projectToJson(paperExampleProject());
    if (planar.is_null())
        j.erase("planar");
    else
        j["planar"] = planar;
    return j;
}

QString loadError(const json& j) {
    try {
        projectFromJson(j);
    } catch (const ProjectError& e) {
        return QString::fromStdString(e.what());
    }
    return {};
}

} // namespace

class TestProjectPlanar : public QObject {
    Q_OBJECT
private slots:
    // Every setting differs from its default, so one that save or load drops shows up.
    void roundTrip_data() {
        QTest::addColumn<int>("vertical");
        QTest::newRow("vertical none") << int(VerticalSource::None);
        QTest::newRow("vertical rsn68_up") << int(VerticalSource::Rsn68Up);
        QTest::newRow("vertical file") << int(VerticalSource::File);
    }
    void roundTrip() {
        QFETCH(int, vertical);
        Project p = paperExampleProject();
        p.model = ModelKind::Planar;
        p.planar.fyHz = 2.5;
        p.planar.ayRatio = 0.45;
        p.planar.theta = 12.0;
        p.planar.normalization = PlanarNormalization::Envelope;
        p.planar.vertical = static_cast<VerticalSource>(vertical);
        if (p.planar.vertical == VerticalSource::File) p.planar.verticalPath = "/data/UP \"x\".AT2";
        const Project q = parseProject(projectToJson(p).dump(2));
        QVERIFY(q.model == ModelKind::Planar);
        QVERIFY(q.planar == p.planar);
        QCOMPARE(q.planar.verticalPath, p.planar.verticalPath);
    }

    // A vertical record file beside the project moves with it: stored relative to the project's
    // directory, resolved against it on load (as the excitation's record is).
    void verticalFileRelativeToProject() {
        QTemporaryDir tmp;
        const std::string dir = tmp.path().toStdString();
        Project p = paperExampleProject();
        p.model = ModelKind::Planar;
        p.planar.vertical = VerticalSource::File;
        p.planar.verticalPath = dir + "/records/UP.AT2";
        const std::string path = dir + "/projects/p.json";
        QVERIFY(QDir().mkpath(QString::fromStdString(dir + "/projects")));
        saveProject(p, path);
        std::ifstream in(path);
        QCOMPARE(json::parse(in)["planar"]["vertical"]["file"].get<std::string>(),
                 std::string("../records/UP.AT2"));
        QCOMPARE(loadProject(path).planar.verticalPath, p.planar.verticalPath);
    }

    // A project written before the planar model: model slab1d and the default settings
    // (f_y 1 Hz, A_y/A_x 0.9, Θ 20 as kinstab-cli's --ay-ratio/--theta defaults, RSN68 UP).
    void oldProjectLoadsWithDefaults() {
        const Project q = projectFromJson(paperJsonWithPlanar(json()));
        QVERIFY(q.model == ModelKind::Slab1D);
        QVERIFY(q.planar == PlanarSettings{});
        QCOMPARE(q.planar.fyHz, 1.0);
        QCOMPARE(q.planar.ayRatio, 0.9);
        QCOMPARE(q.planar.theta, 20.0);
        QVERIFY(q.planar.vertical == VerticalSource::Rsn68Up);
    }

    void badField_data() {
        QTest::addColumn<QByteArray>("planar");
        QTest::addColumn<QString>("message");
        QTest::newRow("negative f_y")
            << QByteArray(R"({"fy_hz": -1})")
            << "planar.fy_hz = -1 Hz: frequency along the walls must be between 0.001 and 1000 Hz";
        QTest::newRow("zero f_y")
            << QByteArray(R"({"fy_hz": 0})")
            << "planar.fy_hz = 0 Hz: frequency along the walls must be between 0.001 and 1000 Hz";
        QTest::newRow("f_y not a number")
            << QByteArray(R"({"fy_hz": "fast"})") << "planar.fy_hz: expected a number";
        QTest::newRow("negative ratio")
            << QByteArray(R"({"ay_ratio": -0.5})")
            << "planar.ay_ratio = -0.5: A_y / A_x must be between 0 and 100";
        QTest::newRow("zero theta") << QByteArray(R"({"theta": 0})")
                                    << "planar.theta = 0: along-wall limit (2 wall length / wall "
                                       "width) must be between 0.001";
        QTest::newRow("unknown normalization")
            << QByteArray(R"({"normalization": "peak"})")
            << "planar.normalization: 'peak' must be product or envelope";
        QTest::newRow("unknown vertical") << QByteArray(R"({"vertical": "pacoima"})")
                                          << "planar.vertical: 'pacoima' must be none";
        QTest::newRow("vertical file without path")
            << QByteArray(R"({"vertical": {"file": ""}})")
            << "planar.vertical.file: '': name the vertical record file";
        QTest::newRow("vertical a number")
            << QByteArray(R"({"vertical": 3})") << "planar.vertical: expected \"none\"";
        QTest::newRow("planar not an object") << QByteArray(R"(7)") << "planar";
    }
    void badField() {
        QFETCH(QByteArray, planar);
        QFETCH(QString, message);
        const QString e = loadError(paperJsonWithPlanar(json::parse(planar.toStdString())));
        QVERIFY2(e.contains(message), qPrintable(e));
    }

    void badModel() {
        json j = paperJsonWithPlanar(json::object());
        j["model"] = "2dof";
        QVERIFY(loadError(j).contains("model = '2dof': must be slab1d or planar"));
    }

    // The case a planar project runs: the 1-DOF case's common inputs plus the settings.
    void caseFromSettings() {
        Project p = paperExampleProject();
        p.planar.fyHz = 5.0;
        p.planar.ayRatio = 0.3;
        p.planar.theta = 8.0;
        const PlanarCase c = planarCaseFrom(p.slab, p.planar, nullptr);
        QCOMPARE(c.fyHz, 5.0);
        QCOMPARE(c.ayRatio, 0.3);
        QCOMPARE(c.theta, 8.0);
        QCOMPARE(c.common.slab.mu, p.slab.slab.mu);
        QCOMPARE(c.common.tstar, p.slab.tstar);
        QCOMPARE(c.tauRef(), p.slab.tauRef());
        QVERIFY(!c.vertical);
        p.planar.fyHz = -1;
        QVERIFY_THROWS_EXCEPTION(InputError, planarCaseFrom(p.slab, p.planar, nullptr));
    }
};

QTEST_APPLESS_MAIN(TestProjectPlanar)
#include "tst_project_planar.moc"
