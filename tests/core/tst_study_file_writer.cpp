// SPDX-License-Identifier: GPL-3.0-or-later
// The study file writer (core/io/StudyFileWriter.h): what the Study tab's fields write reads back
// through the study reader as the study they show, and the keys the fields do not cover stay as
// the opened file had them. The reference is the shipped resources/examples/study-example.json.

#include "core/io/StudyFileWriter.h"
#include "core/io/StudySpecJson.h"

#include <QtTest>

#include <fstream>
#include <sstream>

using namespace kinstab;
using nlohmann::json;

namespace {

const std::string kExamples = KINSTAB_SOURCE_DIR "/resources/examples";

json exampleJson(const std::string& name = "study-example.json") {
    std::ifstream in(kExamples + "/" + name);
    std::stringstream text;
    text << in.rdbuf();
    return json::parse(text.str());
}

// The example's own values, as the Study tab shows them after opening it.
StudyFileFields exampleFields() {
    StudyFileFields f;
    f.folder = "../records";
    f.include = {"*.AT2"};
    f.exclude = {"*UP*", "*DWN*"};
    f.measure = "pga";
    f.saPeriodS = 1.0;
    f.mu = "0.4, 0.6";
    f.tstar = "0.099";
    f.maxG = 3;
    f.scanStepG = 0.02;
    return f;
}

} // namespace

class TestStudyFileWriter : public QObject {
    Q_OBJECT
private slots:
    void writtenFileReadsAsTheOpenedStudy();
    void keysTheFieldsDoNotCoverAreKept();
    void measureAndFloorFilterFollowTheFields();
    void blockStudyKeepsItsBlockAndNoSlab();
};

// The shipped block study (resources/examples/study-block.json): the file refuses mu and t*
// beside a block, so the tab's (empty) slab lists are not written and the block is kept.
void TestStudyFileWriter::blockStudyKeepsItsBlockAndNoSlab() {
    StudyFileFields f = exampleFields();
    f.mu.clear();
    f.tstar.clear();
    const json base = exampleJson("study-block.json");
    const json j = json::parse(studyFileText(base, f));
    QVERIFY(!j["parameters"].contains("mu"));
    QVERIFY(!j["parameters"].contains("tstar"));
    QCOMPARE(j["block"], base["block"]);
    QCOMPARE(j["parameters"]["levels"], base["parameters"]["levels"]);
    const StudySpec opened = loadStudy(kExamples + "/study-block.json");
    const StudySpec written = studyFromJsonText(j.dump(), kExamples);
    QVERIFY(written.block && opened.block && *written.block == *opened.block);
    QVERIFY(written.levels == opened.levels);
}

void TestStudyFileWriter::writtenFileReadsAsTheOpenedStudy() {
    const StudySpec opened = loadStudy(kExamples + "/study-example.json");
    const StudySpec written =
        studyFromJsonText(studyFileText(exampleJson(), exampleFields()), kExamples);
    QCOMPARE(written.name, opened.name);
    QCOMPARE(written.records.size(), opened.records.size());
    for (std::size_t i = 0; i < opened.records.size(); ++i)
        QCOMPARE(written.records[i].file, opened.records[i].file);
    QVERIFY(written.mu == opened.mu);
    QVERIFY(written.tstar == opened.tstar);
    QCOMPARE(written.intensity.kind, opened.intensity.kind);
    QCOMPARE(written.limit, opened.limit);
    QCOMPARE(written.search.to, opened.search.to);
    QCOMPARE(written.search.scanStep, opened.search.scanStep);
    QCOMPARE(written.search.tolerance, opened.search.tolerance);
}

void TestStudyFileWriter::keysTheFieldsDoNotCoverAreKept() {
    json base = exampleJson();
    base["parameters"]["wall_width_in"] = 7.6; // the tab's field is t*: the width goes
    const json j = json::parse(studyFileText(base, exampleFields()));
    QCOMPARE(j["name"].get<std::string>(), base["name"].get<std::string>());
    QCOMPARE(j["parameters"]["limit"].get<double>(), 1.0);
    QCOMPARE(j["search"]["tolerance_g"].get<double>(), 1e-4);
    QVERIFY(!j["parameters"].contains("wall_width_in"));
    QCOMPARE(j["version"].get<int>(), kStudyVersion);
    // The opened records array is written back as it was, per-record scales included.
    StudyFileFields kept = exampleFields();
    kept.openedRecords = json::array({{{"path", "a.AT2"}, {"scale", 2.0}}});
    QCOMPARE(json::parse(studyFileText(base, kept))["records"], *kept.openedRecords);
}

void TestStudyFileWriter::measureAndFloorFilterFollowTheFields() {
    StudyFileFields f = exampleFields();
    f.measure = "sa";
    f.saPeriodS = 0.5;
    f.floorPeriods = "0.5, 1";
    const json sa = json::parse(studyFileText(exampleJson(), f));
    QCOMPARE(sa["intensity"]["period_s"].get<double>(), 0.5);
    QCOMPARE(sa["parameters"]["floor_filter"]["periods_s"].get<std::string>(),
             std::string("0.5, 1"));
    // Back to PGA without floors: the period and the filter go, not left behind.
    f.measure = "pga";
    f.floorPeriods.reset();
    const json pga = json::parse(studyFileText(sa, f));
    QVERIFY(!pga["intensity"].contains("period_s"));
    QVERIFY(!pga["parameters"].contains("floor_filter"));
}

QTEST_GUILESS_MAIN(TestStudyFileWriter)
#include "tst_study_file_writer.moc"
