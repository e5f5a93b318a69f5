// SPDX-License-Identifier: GPL-3.0-or-later
// The study engine (docs/studies.md): the fixed case order (mu slowest, then t*, then the floor
// filter, records fastest), shards, the rows on one thread and on three (the same bytes), a row
// read back equal to the one written, cancel (also run under ThreadSanitizer, scripts/tsan.sh),
// a run continued after its first rows (study --resume), and records read once: a record
// rewritten or deleted during the run does not change the rows still to come.

#include "core/io/AtomicFile.h"
#include "core/io/StudyRowJson.h"
#include "core/io/StudySpecJson.h"
#include "core/study/StudyRecords.h"
#include "core/study/StudyRunner.h"

#include <nlohmann/json.hpp>

#include <QtTest>

#include <QDir>
#include <QFile>
#include <QTemporaryDir>

#include <algorithm>
#include <sstream>

using namespace kinstab;

namespace {

const std::string kSpec = KINSTAB_TEST_DATA "/study/small-study.json";

StudySpec loaded(const std::string& path) {
    StudySpec s = loadStudy(path);
    loadStudyRecords(s);
    return s;
}

std::vector<StudyRow> rowsOfRun(const StudySpec& s, unsigned threads) {
    StudyRunOptions o;
    o.threads = threads;
    return runStudyRows(s, o);
}

std::string runAll(const StudySpec& s, unsigned threads) {
    return studyRowsText(rowsOfRun(s, threads));
}

} // namespace

class TestStudyRunner : public QObject {
    Q_OBJECT
private slots:
    void casesFollowTheDocumentedOrder() {
        const StudySpec s = loadStudy(kSpec);
        // 3 records x mu {0.5, 0.7} x t* {0.099} x floors {ground, T = 0.5 s}.
        QCOMPARE(studyCaseCount(s), std::size_t(12));
        QCOMPARE(studyParameterSets(s), std::size_t(4));
        const StudyCase c7 = studyCase(s, 7); // set 2 = (mu 0.7, ground), record 1
        QCOMPARE(c7.set, std::size_t(2));
        QCOMPARE(c7.mu, 0.7);
        QVERIFY(!c7.floor);
        QVERIFY(c7.record->label.find("PEL090") != std::string::npos);
        const StudyCase c11 = studyCase(s, 11); // set 3 = (mu 0.7, T = 0.5 s), record 2
        QCOMPARE(c11.floor->period, 0.5);
        QVERIFY(c11.record->label.find("PEL180") != std::string::npos);
    }
    void shardsPartitionTheCases() {
        QVERIFY(!parseShard("0/3") && !parseShard("4/3") && !parseShard("a/b") && !parseShard("3"));
        QVERIFY(!parseShard("1/3x") && !parseShard("-1/3"));
        const Shard k2 = *parseShard("2/3");
        QVERIFY(k2.owns(1) && k2.owns(4) && !k2.owns(0) && !k2.owns(2));
    }
    void threadsGiveTheSameRows() {
        const StudySpec s = loaded(kSpec);
        const std::string one = runAll(s, 1);
        QCOMPARE(runAll(s, 3), one);
        std::istringstream in(one);
        std::string line;
        for (std::size_t i = 0; std::getline(in, line); ++i) {
            const StudyRow r = parseStudyRow(line);
            QCOMPARE(r.index, i);
            QCOMPARE(studyRowLine(r), line); // read back and written again: the same bytes
        }
    }
    void rowsHandedOnAreTheRowsReadBack() {
        // The GUI, the report and Python take the rows as runStudy hands them on, the CLI writes
        // them: each must be the row its line reads back as, field for field.
        const std::vector<StudyRow> rows = rowsOfRun(loaded(kSpec), 2);
        QCOMPARE(rows.size(), std::size_t(12));
        for (const StudyRow& r : rows) {
            const std::string line = studyRowLine(r);
            QVERIFY2(parseStudyRow(line) == r, line.c_str());
        }
    }
    void cancelStopsAfterTheBlockInHand() {
        // 11 mu x 3 records x 2 floors = 66 cases; one thread runs blocks of 16.
        nlohmann::json j = nlohmann::json::parse(readWholeFile(kSpec));
        j["parameters"]["mu"] = "0.3:0.8:0.05";
        StudySpec s = studyFromJsonText(j.dump(), KINSTAB_TEST_DATA "/study");
        loadStudyRecords(s);
        QCOMPARE(studyCaseCount(s), std::size_t(66));
        SweepControl control;
        control.onProgress = [&](std::size_t, std::size_t) { control.cancel(); };
        StudyRunOptions o;
        o.threads = 1;
        o.control = &control;
        std::string text;
        QCOMPARE(runStudy(s, o, [&](const std::vector<StudyRow>& b) { text += studyRowsText(b); }),
                 std::size_t(16));
        QCOMPARE(std::count(text.begin(), text.end(), '\n'), 16L);
        // Cancelled before it starts: nothing.
        text.clear();
        QCOMPARE(runStudy(s, o, [&](const std::vector<StudyRow>& b) { text += studyRowsText(b); }),
                 std::size_t(0));
        QVERIFY(text.empty());
    }
    void aRunContinuesAfterItsFirstRows() {
        const StudySpec s = loaded(kSpec);
        const std::string all = runAll(s, 1);
        StudyRunOptions o;
        o.shard = *parseShard("2/3"); // cases 1, 4, 7, 10
        QCOMPARE(shardCaseCount(s, o.shard), std::size_t(4));
        std::string shard, rest;
        runStudy(s, o, [&](const std::vector<StudyRow>& b) { shard += studyRowsText(b); });
        o.done = 1;
        QCOMPARE(runStudy(s, o, [&](const std::vector<StudyRow>& b) { rest += studyRowsText(b); }),
                 std::size_t(3));
        QCOMPARE(rest, shard.substr(shard.find('\n') + 1)); // cases 4, 7, 10
        o.done = 4;
        QCOMPARE(runStudy(s, o, [](const std::vector<StudyRow>&) { QFAIL("no rows were left"); }),
                 std::size_t(0));
    }
    void recordsAreReadOnce() {
        // The study's records copied, so that they can be rewritten and deleted mid-study.
        QTemporaryDir dir;
        const QDir records(KINSTAB_SOURCE_DIR "/resources/records");
        const QStringList names = {"RSN6_IMPVALL.I_I-ELC180.AT2", "RSN68_SFERN_PEL090.AT2",
                                   "RSN68_SFERN_PEL180.AT2"};
        for (const QString& n : names)
            QVERIFY(QFile::copy(records.filePath(n), dir.filePath(n)));
        nlohmann::json j = nlohmann::json::parse(readWholeFile(kSpec));
        j["records"] = {{{"path", "."}, {"include", {"*.AT2"}}}};
        StudySpec s = studyFromJsonText(j.dump(), dir.path().toStdString());
        loadStudyRecords(s);
        const std::string before = runAll(s, 2);
        // One record rewritten as another, one deleted: the rows stay those of the records
        // as they were read.
        QVERIFY(QFile::remove(dir.filePath(names[0])));
        QVERIFY(QFile::copy(records.filePath("Rinaldi228.AT2"), dir.filePath(names[0])));
        QVERIFY(QFile::remove(dir.filePath(names[1])));
        QCOMPARE(runAll(s, 2), before);
        // A spec whose records were never read runs no case (a programming error).
        StudySpec unread = studyFromJsonText(j.dump(), dir.path().toStdString());
        QVERIFY_THROWS_EXCEPTION(std::logic_error, runAll(unread, 1));
    }
};

QTEST_APPLESS_MAIN(TestStudyRunner)
#include "tst_study_runner.moc"
