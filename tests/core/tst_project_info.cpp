// SPDX-License-Identifier: GPL-3.0-or-later
// The project's title-block metadata (core/io/ProjectInfo.h): read from and written to the project
// file, every field's length limited and named when too long, revision dates checked, older
// files without "info" unchanged.

#include "core/base/InputLimits.h"
#include "core/io/Project.h"

#include <QtTest>

#include <clocale>

using namespace kinstab;

namespace {

ProjectInfo sample() {
    ProjectInfo in;
    in.engineer = "A. N. Example, P.E.";
    in.registration = "S 00000";
    in.firm = "Example Structural Engineers";
    in.client = "Example Owner LLC";
    in.projectNumber = "EX-1";
    in.siteAddress = "100 Example Avenue, Los Angeles";
    in.preparedBy = "A. N. Example";
    in.checkedBy = "B. C. Checker";
    in.revisions = {{"0", "2026-11-02", "Issued for review"}, {"A", "2026-11-24", "For permit"}};
    return in;
}

std::string loadError(const nlohmann::json& info) {
    nlohmann::json j = projectToJson(paperExampleProject());
    j["info"] = info;
    try {
        parseProject(j.dump());
    } catch (const ProjectError& e) {
        return e.what();
    }
    return {};
}

} // namespace

class TestProjectInfo : public QObject {
    Q_OBJECT
private slots:
    void roundTrip() {
        Project p = paperExampleProject();
        p.info = sample();
        const Project q = parseProject(projectToJson(p).dump(2));
        QCOMPARE(projectToJson(q).dump(), projectToJson(p).dump());
        QCOMPARE(q.info.checkedBy, std::string("B. C. Checker"));
        QCOMPARE(q.info.revisions.size(), std::size_t(2));
        QCOMPARE(q.info.revisions.back().date, std::string("2026-11-24"));
    }
    void roundTripInGermanLocale() {
        // Text and ISO dates only: a decimal comma locale changes nothing.
        const char* old = std::setlocale(LC_ALL, "de_DE.UTF-8");
        Project p = paperExampleProject();
        p.info = sample();
        const std::string text = projectToJson(p).dump(2);
        QCOMPARE(projectToJson(parseProject(text)).dump(2), text);
        std::setlocale(LC_ALL, old ? old : "C");
    }
    void olderFilesHaveNoInfo() {
        const Project p = parseProject(projectToJson(paperExampleProject()).dump());
        QVERIFY(p.info.empty());
        QVERIFY(!projectToJson(p).contains("info")); // not written when empty
    }
    void badFields_data() {
        QTest::addColumn<QString>("key");
        QTest::addColumn<QString>("value"); // JSON text of the value
        QTest::addColumn<QString>("message");
        const std::string longText(limits::kMaxNameChars + 1, 'x');
        QTest::newRow("engineer too long")
            << "engineer" << QString::fromStdString("\"" + longText + "\"")
            << "info.engineer: 201 characters, more than the limit of 200";
        QTest::newRow("client not text") << "client"
                                         << "42"
                                         << "info.client";
        QTest::newRow("revisions not a list") << "revisions"
                                              << "\"A\""
                                              << "info.revisions";
        QTest::newRow("German date")
            << "revisions"
            << R"([{"id": "0", "date": "24.11.2026", "description": ""}])"
            << "info.revisions[0].date = '24.11.2026': must be a date YYYY-MM-DD";
        QTest::newRow("month 13") << "revisions"
                                  << R"([{"id": "0", "date": "2026-13-01", "description": ""}])"
                                  << "info.revisions[0].date";
        QTest::newRow("mark of 13 characters")
            << "revisions"
            << R"([{"id": "Rev. 2026-001", "date": "2026-11-01"}])"
            << "info.revisions[0].id: 13 characters, more than the limit of 12";
        QTest::newRow("no mark") << "revisions"
                                 << R"([{"id": "", "date": "2026-11-01", "description": ""}])"
                                 << "info.revisions[0].id: empty";
    }
    void badFields() {
        QFETCH(QString, key);
        QFETCH(QString, value);
        QFETCH(QString, message);
        nlohmann::json info = projectInfoToJson(sample());
        info[key.toStdString()] = nlohmann::json::parse(value.toStdString());
        const std::string e = loadError(info);
        QVERIFY2(QString::fromStdString(e).contains(message), e.c_str());
    }
    void tooManyRevisions() {
        ProjectInfo in = sample();
        in.revisions.assign(limits::kMaxRevisions + 1, {"0", "2026-01-01", ""});
        const std::string e = loadError(projectInfoToJson(in));
        QVERIFY2(e.find("info.revisions: 51 revisions, more than the limit of 50") !=
                     std::string::npos,
                 e.c_str());
    }
    // Issue 31: the texts the report prints refuse controls and bidirectional formatting (the
    // cases of tests/core/tst_display_text.cpp); the description alone keeps its line breaks;
    // lengths are characters, so 200 two-byte characters are a 200-character name.
    void printedTextIsWhatItReads() {
        nlohmann::json info = projectInfoToJson(sample());
        info["registration"] = "S 12345\u202E67890";
        QCOMPARE(loadError(info),
                 std::string("info.registration: contains U+202E (a bidirectional override) "
                             "at character 8"));
        Project p = paperExampleProject();
        std::string e200;
        for (int i = 0; i < 200; ++i)
            e200 += "\u00E9";
        p.name = e200;
        p.building.name = e200;
        p.info.firm = e200;
        p.description = "First line.\nSecond line.\r\nThird.";
        QCOMPARE(validateProject(p), std::string());
        QCOMPARE(parseProject(projectToJson(p).dump()).description, p.description);
        p.building.name = "Tower\nA";
        QCOMPARE(validateProject(p),
                 std::string("building.name: contains U+000A (a line break in one-line text) at "
                             "character 6"));
        p.building.name = "Tower A";
        p.description += "\u202E";
        QVERIFY(validateProject(p).find("description: contains U+202E") == 0);
    }
    void shippedExamplesCarryExampleMetadata() {
        for (const char* f : {"paper-16-story.json", "paper-16-story-record.json",
                              "paper-planar.json", "paper-16-story-floors.json"}) {
            const Project p =
                loadProject(std::string(KINSTAB_SOURCE_DIR "/resources/examples/") + f);
            QVERIFY2(p.info.engineer.find("(example)") != std::string::npos, f);
            QVERIFY2(!p.info.revisions.empty(), f);
        }
    }
};

QTEST_APPLESS_MAIN(TestProjectInfo)
#include "tst_project_info.moc"
