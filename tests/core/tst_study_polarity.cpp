// SPDX-License-Identifier: GPL-3.0-or-later
// A study's "polarity": "both" (docs/studies.md, issue 33): each record runs as given and
// inverted as two neighbouring cases whose rows name their polarity; the inverted case's
// critical intensity is the one of a record file written here with every sign flipped and run
// as given (an independent route: the file, not the engine, inverts it); a study without the key,
// or with "normal", writes the same bytes and fingerprint as before; the fragility and the record
// statistics count both rows.

#include "core/io/AtomicFile.h"
#include "core/io/StudyRowJson.h"
#include "core/io/StudySpecJson.h"
#include "core/records/RecordReader.h"
#include "core/study/Fragility.h"
#include "core/study/StudyRecords.h"
#include "core/study/StudyRunner.h"

#include <nlohmann/json.hpp>

#include <QFile>
#include <QTemporaryDir>
#include <QtTest>

#include <sstream>

using namespace kinstab;

namespace {

const QString kRecord = KINSTAB_SOURCE_DIR "/resources/records/RSN68_SFERN_PEL090.AT2";

// The AT2 file with each value's sign flipped in its text: "-.21E-02" <-> ".21E-02" (exact).
QString writeFlipped(const QTemporaryDir& dir) {
    QFile in(kRecord);
    if (!in.open(QIODevice::ReadOnly)) return {};
    const QStringList lines = QString::fromLatin1(in.readAll()).split('\n');
    QStringList out = lines.mid(0, 4); // the PEER header: 4 lines
    for (const QString& line : lines.mid(4)) {
        QStringList values;
        for (const QString& v : line.split(' ', Qt::SkipEmptyParts))
            values << (v.startsWith('-') ? v.mid(1) : "-" + v);
        out << "  " + values.join("  ");
    }
    const QString path = dir.filePath("flipped.AT2");
    writeFileAtomically(path.toStdString(), out.join('\n').toStdString());
    return path;
}

std::string specText(const QStringList& records, const char* polarity) {
    nlohmann::json j = {{"format", "kinstab-study"},
                        {"version", 1},
                        {"records", nlohmann::json::array()},
                        {"parameters", {{"mu", {0.6}}, {"tstar", {0.099}}}},
                        {"search", {{"max_g", 2.0}, {"scan_step_g", 0.05}, {"tolerance_g", 1e-4}}}};
    for (const QString& r : records)
        j["records"].push_back({{"path", r.toStdString()}});
    if (polarity) j["polarity"] = polarity;
    return j.dump();
}

StudySpec loaded(const std::string& text) {
    StudySpec s = studyFromJsonText(text, "");
    loadStudyRecords(s);
    return s;
}

std::string runAll(const StudySpec& s) {
    std::string text;
    StudyRunOptions o;
    o.threads = 2;
    runStudy(s, o, [&text](const std::vector<StudyRow>& b) { text += studyRowsText(b); });
    return text;
}

std::vector<StudyRow> rowsOf(const std::string& text) {
    std::vector<StudyRow> rows;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
        rows.push_back(parseStudyRow(line));
    return rows;
}

} // namespace

class TestStudyPolarity : public QObject {
    Q_OBJECT
private slots:
    void casesAlternateNormalAndInverted() {
        const StudySpec s = studyFromJsonText(
            specText({kRecord, KINSTAB_SOURCE_DIR "/resources/records/RSN68_SFERN_PEL180.AT2"},
                     "both"),
            "");
        QCOMPARE(studyCaseCount(s), std::size_t(4)); // 2 records x 2 polarities x 1 set
        QCOMPARE(studyParameterSets(s), std::size_t(1));
        for (std::size_t i = 0; i < 4; ++i) {
            const StudyCase c = studyCase(s, i);
            QCOMPARE(c.inverted, i % 2 == 1);
            QCOMPARE(c.record, &s.records[i / 2]);
            QCOMPARE(studyRowInputs(s, c).polarity,
                     std::optional<std::string>(i % 2 ? "inverted" : "normal"));
        }
    }
    void caseGroundFlipsEverySample() {
        const Accelerogram a = readRecord(kRecord.toStdString());
        const Accelerogram b = caseGround(a, true);
        QCOMPARE(b.samples.size(), a.samples.size());
        QCOMPARE(b.dt, a.dt);
        for (std::size_t i = 0; i < a.samples.size(); ++i)
            QCOMPARE(b.samples[i], -a.samples[i]);
        QCOMPARE(caseGround(a, false).samples, a.samples);
    }
    void invertedEqualsTheFlippedFileRunAsGiven() {
        QTemporaryDir dir;
        const QString flipped = writeFlipped(dir);
        QVERIFY(!flipped.isEmpty());
        const std::vector<StudyRow> both = rowsOf(runAll(loaded(specText({kRecord}, "both"))));
        const std::vector<StudyRow> file = rowsOf(runAll(loaded(specText({flipped}, nullptr))));
        QCOMPARE(both.size(), std::size_t(2));
        QCOMPARE(file.size(), std::size_t(1));
        QCOMPARE(both[0].polarity, std::optional<std::string>("normal"));
        QCOMPARE(both[1].polarity, std::optional<std::string>("inverted"));
        QVERIFY(!file[0].polarity);
        QVERIFY(file[0].criticalIntensity);
        QCOMPARE(both[1].criticalIntensity, file[0].criticalIntensity);
        QCOMPARE(both[1].criticalPeak, file[0].criticalPeak);
        QCOMPARE(both[1].recordIntensity, file[0].recordIntensity);
        QCOMPARE(both[1].runs, file[0].runs);
        // The fragility counts both rows as records of the set, and so do the statistics.
        const std::vector<Fragility> f = studyFragility(both, {0, 1, 0.9, 1});
        QCOMPARE(f.size(), std::size_t(1));
        QCOMPARE(f[0].records, std::size_t(2));
        QCOMPARE(f[0].statistics.collapsed + f[0].statistics.censored, std::size_t(2));
        QCOMPARE(f[0].points.size(), f[0].statistics.collapsed);
    }
    void withoutTheKeyTheRowsAreAsBefore() {
        const StudySpec none = loaded(specText({kRecord}, nullptr));
        const StudySpec normal = loaded(specText({kRecord}, "normal"));
        const StudySpec both = loaded(specText({kRecord}, "both"));
        QCOMPARE(normal.fingerprint, none.fingerprint);
        QVERIFY(both.fingerprint != none.fingerprint);
        const std::string rows = runAll(none);
        QCOMPARE(runAll(normal), rows);
        QVERIFY(rows.find("polarity") == std::string::npos);
        // The normal row of "both" is the record's row, case numbering and fingerprint apart.
        const StudyRow before = rowsOf(rows).front();
        const StudyRow asGiven = rowsOf(runAll(both)).front();
        QCOMPARE(asGiven.criticalIntensity, before.criticalIntensity);
        QCOMPARE(asGiven.runs, before.runs);
    }
    void aBadPolarityIsRefusedByName() {
        try {
            (void)studyFromJsonText(specText({kRecord}, "reversed"), "");
            QFAIL("accepted polarity \"reversed\"");
        } catch (const StudyError& e) {
            QVERIFY2(std::string(e.what()).find("polarity") != std::string::npos, e.what());
            QVERIFY2(std::string(e.what()).find("reversed") != std::string::npos, e.what());
        }
    }
};

QTEST_MAIN(TestStudyPolarity)
#include "tst_study_polarity.moc"
