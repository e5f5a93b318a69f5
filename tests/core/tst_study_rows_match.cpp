// SPDX-License-Identifier: GPL-3.0-or-later
// A results file is shown or printed as a study's only when its rows are that study's cases:
// rows written from the study's own cases match; a row whose level, motion or record scale is
// not the study file's is named, as one whose mu differs (the fields a study with a building,
// fitted-sine motions and scaled records adds to the rows); and rows of the same inputs but
// another fingerprint (a record's bytes, the search step) are refused too.

#include "core/study/StudyCase.h"
#include "core/study/StudyFingerprint.h"
#include "core/study/StudyRowsMatch.h"

#include <QtTest>

using namespace kinstab;

namespace {

StudyRecord record(const std::string& name, double scale) {
    StudyRecord r;
    r.file = "/data/" + name;
    r.label = name;
    r.scale = scale;
    r.sha256 = std::string(64, name[0] == 'a' ? '1' : '2'); // as if read
    return r;
}

StudySpec spec() {
    StudySpec s;
    s.records = {record("a.AT2", 2.0), record("b.AT2", 0.5)};
    s.asGiven = true;
    s.mu = {0.4, 0.6};
    s.tstar = {0.099};
    s.floors = {};
    s.building = StudyBuilding{};
    s.levels = {1, 8};
    s.motions = {StudyMotion::Record, StudyMotion::FittedSine};
    s.motionGiven = true;
    s.search.to = 3.0;
    s.fingerprint = studyFingerprint(s);
    return s;
}

// The row a run of case i writes, as far as the comparison reads it (no collapse).
StudyRow rowOf(const StudySpec& s, std::size_t i) {
    const StudyCase c = studyCase(s, i);
    StudyRow r = studyRowInputs(s, c);
    r.scale = c.record->scale;
    return r;
}

std::vector<StudyRow> rowsOf(const StudySpec& s) {
    std::vector<StudyRow> rows;
    for (std::size_t i = 0; i < studyCaseCount(s); ++i)
        rows.push_back(rowOf(s, i));
    return rows;
}

} // namespace

class TestStudyRowsMatch : public QObject {
    Q_OBJECT
private slots:
    void ownRowsMatch() {
        const StudySpec s = spec();
        QCOMPARE(studyCaseCount(s), std::size_t(16)); // 2 mu x 2 levels x 2 motions x 2 records
        QCOMPARE(QString::fromStdString(studyRowsMismatch(s, "/data", rowsOf(s))), QString());
    }

    void otherLevelMotionOrScaleIsNamed() {
        const StudySpec s = spec();
        std::vector<StudyRow> rows = rowsOf(s);
        rows[3].level = 8 + 1 - *rows[3].level; // 1 <-> 8
        QVERIFY(studyRowsMismatch(s, "/data", rows).find("row 4: level") == 0);
        rows = rowsOf(s);
        rows[1].motion = rows[1].motion == "record" ? "fitted_sine" : "record";
        QVERIFY(studyRowsMismatch(s, "/data", rows).find("row 2: motion") == 0);
        rows = rowsOf(s);
        rows[0].scale = 1.0;
        QVERIFY(studyRowsMismatch(s, "/data", rows).find("row 1: record scale 1") == 0);
        rows = rowsOf(s);
        rows[5].mu = 0.5;
        QVERIFY(studyRowsMismatch(s, "/data", rows).find("row 6: mu = 0.5") == 0);
    }

    void anotherFingerprintIsNamed() {
        StudySpec s = spec();
        const std::vector<StudyRow> rows = rowsOf(s);
        s.records[1].sha256 = std::string(64, '3'); // b.AT2's bytes changed since the run
        s.fingerprint = studyFingerprint(s);
        const std::string m = studyRowsMismatch(s, "/data", rows);
        QVERIFY2(m.find("row 1 is of study " + rows[0].study) == 0, m.c_str());
        QVERIFY2(m.find("the study file and its records are study " + s.fingerprint) !=
                     std::string::npos,
                 m.c_str());
    }
};

QTEST_APPLESS_MAIN(TestStudyRowsMatch)
#include "tst_study_rows_match.moc"
