// SPDX-License-Identifier: GPL-3.0-or-later
// A study's fingerprint (core/study/StudyFingerprint.h) follows what decides its rows - a
// parameter, the search's step, a record's bytes - and nothing else: not the study's name nor
// where its records are (the same files named by absolute paths or from another folder).

#include "core/io/AtomicFile.h"
#include "core/io/StudySpecJson.h"
#include "core/study/StudyFingerprint.h"
#include "core/study/StudyRecords.h"

#include <nlohmann/json.hpp>

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QtTest>

using namespace kinstab;

namespace {

const std::string kSpec = KINSTAB_TEST_DATA "/study/small-study.json";

std::string fingerprintOf(const nlohmann::json& j, const std::string& dir) {
    StudySpec s = studyFromJsonText(j.dump(), dir);
    hashStudyRecords(s);
    StudySpec loaded = studyFromJsonText(j.dump(), dir);
    loadStudyRecords(loaded); // a run's fingerprint is the check's
    if (loaded.fingerprint != s.fingerprint) return "hash and load differ";
    return s.fingerprint;
}

} // namespace

class TestStudyFingerprint : public QObject {
    Q_OBJECT
    nlohmann::json spec_ = nlohmann::json::parse(readWholeFile(kSpec));
    const std::string dir_ = KINSTAB_TEST_DATA "/study";

private slots:
    void followsTheInputs() {
        const std::string base = fingerprintOf(spec_, dir_);
        QVERIFY(isStudyFingerprint(base));
        QCOMPARE(fingerprintOf(spec_, dir_), base); // the same study: the same fingerprint
        nlohmann::json j = spec_;
        j["parameters"]["mu"] = {0.5, 0.8};
        QVERIFY(fingerprintOf(j, dir_) != base);
        j = spec_;
        j["search"]["scan_step_g"] = 0.04;
        QVERIFY(fingerprintOf(j, dir_) != base);
        j = spec_;
        j["records"][0]["scale"] = 2;
        QVERIFY(fingerprintOf(j, dir_) != base);
    }
    void ignoresNameAndPlace() {
        const std::string base = fingerprintOf(spec_, dir_);
        nlohmann::json j = spec_;
        j["name"] = "another name";
        j["records"][0]["path"] =
            KINSTAB_SOURCE_DIR "/resources/records/RSN6_IMPVALL.I_I-ELC180.AT2";
        QCOMPARE(fingerprintOf(j, dir_), base);
    }
    void followsTheRecordsBytes() {
        QTemporaryDir dir;
        const QString file = dir.filePath("r.AT2");
        QVERIFY(QFile::copy(KINSTAB_SOURCE_DIR "/resources/records/RSN68_SFERN_PEL090.AT2", file));
        const nlohmann::json j = {
            {"format", "kinstab-study"}, {"version", 1}, {"records", {{{"path", "r.AT2"}}}}};
        const std::string before = fingerprintOf(j, dir.path().toStdString());
        QFile f(file);
        QVERIFY(f.open(QIODevice::ReadWrite));
        QByteArray bytes = f.readAll();
        const qsizetype digit = bytes.lastIndexOf('1'); // one sample's digit changed
        QVERIFY(digit > 0);
        bytes[digit] = '2';
        QVERIFY(f.seek(0) && f.write(bytes) == bytes.size());
        f.close();
        QVERIFY(fingerprintOf(j, dir.path().toStdString()) != before);
    }
};

QTEST_APPLESS_MAIN(TestStudyFingerprint)
#include "tst_study_fingerprint.moc"
