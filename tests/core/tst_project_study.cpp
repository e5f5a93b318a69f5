// SPDX-License-Identifier: GPL-3.0-or-later
// The project's study (core/io/StudyJson.h): saved relative to the project's folder and read
// back to the same files, absent in files without it, and a study file that is missing or not a
// study is a ProjectError naming study.spec and the path.

#include "core/io/Project.h"

#include <QTemporaryDir>
#include <QtTest>

#include <filesystem>

using namespace kinstab;

namespace {

const std::string kExamples = KINSTAB_SOURCE_DIR "/resources/examples/";

std::string loadError(const nlohmann::json& study) {
    nlohmann::json j = projectToJson(paperExampleProject());
    j["study"] = study;
    try {
        parseProject(j.dump(), kExamples);
    } catch (const ProjectError& e) {
        return e.what();
    }
    return {};
}

} // namespace

class TestProjectStudy : public QObject {
    Q_OBJECT

private slots:
    // resources/examples/paper-16-story-study.json names study-example.json beside it.
    void exampleResolvesBesideTheProject() {
        const Project p = loadProject(kExamples + "paper-16-story-study.json");
        QVERIFY(p.study.has_value());
        QCOMPARE(std::filesystem::path(p.study->spec).lexically_normal(),
                 std::filesystem::absolute(kExamples + "study-example.json").lexically_normal());
        QVERIFY(p.study->results.empty());
    }

    void roundTripRelativeToTheProject() {
        Project p = paperExampleProject();
        const std::string spec =
            std::filesystem::absolute(kExamples + "study-example.json").lexically_normal();
        p.study = ProjectStudy{spec, std::filesystem::path(kExamples) / "runs" / "rows.jsonl",
                               std::nullopt};
        // Stored relative to the project's folder, as a record's file is.
        const nlohmann::json j = projectToJson(p, kExamples);
        QCOMPARE(j["study"]["spec"].get<std::string>(), std::string("study-example.json"));
        QCOMPARE(j["study"]["results"].get<std::string>(), std::string("runs/rows.jsonl"));
        // Saved elsewhere and loaded back: the same files.
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const std::string path = dir.filePath("p.json").toStdString();
        saveProject(p, path);
        const Project q = loadProject(path);
        QVERIFY(q.study.has_value());
        QCOMPARE(std::filesystem::path(q.study->spec).lexically_normal().string(), spec);
        QCOMPARE(std::filesystem::path(q.study->results).lexically_normal(),
                 std::filesystem::path(p.study->results).lexically_normal());
    }

    void absentStaysAbsent() {
        const Project p = loadProject(kExamples + "paper-16-story.json");
        QVERIFY(!p.study.has_value());
        QVERIFY(!projectToJson(p).contains("study"));
    }

    void badStudyNamesTheField() {
        std::string e = loadError({{"spec", "no-such-study.json"}});
        QVERIFY2(e.find("study.spec") != std::string::npos, e.c_str());
        QVERIFY2(e.find("no-such-study.json") != std::string::npos, e.c_str());
        e = loadError({{"spec", "paper-16-story.json"}}); // a project, not a study
        QVERIFY2(e.find("study.spec") != std::string::npos, e.c_str());
        e = loadError({{"results", "rows.jsonl"}});
        QVERIFY2(e.find("study.spec") != std::string::npos, e.c_str());
        e = loadError({{"spec", std::string(5000, 'x')}});
        QVERIFY2(e.find("study.spec") != std::string::npos, e.c_str());
        e = loadError(42);
        QVERIFY2(e.find("study") != std::string::npos, e.c_str());
    }
};

QTEST_GUILESS_MAIN(TestProjectStudy)
#include "tst_project_study.moc"
