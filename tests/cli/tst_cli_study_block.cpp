// SPDX-License-Identifier: GPL-3.0-or-later
// A study of a free-standing block (docs/studies.md, "A block instead of the slab"), run as a user
// would: per record the critical peak is the critical_amplitude_g `kinstab-cli rocking --record
// FILE --critical` gives with the study's search as flags (the same search on the same motion:
// equal to the last bit); the rows carry the block instead of the slab's parameters, the
// fragility fits them and names the block, a changed block is another study; bad block keys are
// exit 2 naming the key.

#include "CliRun.h"
#include "FileBytes.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QtTest>

namespace {

const QString kRecords = QStringLiteral(KINSTAB_SOURCE_DIR "/resources/records/");
const QStringList kFiles = {"RSN6_IMPVALL.I_I-ELC180.AT2", "RSN68_SFERN_PEL090.AT2",
                            "Rinaldi228.AT2"};
constexpr double kMaxG = 0.8, kStepG = 0.02, kToleranceG = 1e-4;

QByteArray recordsJson() {
    QByteArray a = "\"records\": [";
    for (int i = 0; i < kFiles.size(); ++i)
        a += QByteArray(i ? ", " : "") + "{\"path\": \"" + (kRecords + kFiles[i]).toUtf8() + "\"}";
    return a + "]";
}

// A study of the three records with the given members (JSON member texts).
QByteArray studyWith(const QByteArray& members) {
    return "{\"format\": \"kinstab-study\", \"version\": 1, " + recordsJson() + ", " + members +
           ", \"search\": {\"max_g\": 0.8, \"scan_step_g\": 0.02, \"tolerance_g\": 1e-4}}";
}

const QByteArray kBlock = "\"block\": {\"half_width_m\": 0.15, \"half_height_m\": 0.6, "
                          "\"mu\": null, \"restitution\": null, \"linear\": false}";

QString num(double x) {
    return QString::number(x, 'g', 17);
}

} // namespace

class TestCliStudyBlock : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;
    QList<QJsonObject> rows_;

    QString write(const QString& name, const QByteArray& text) {
        const QString path = dir_.filePath(name);
        writeBytes(path, text);
        return path;
    }

private slots:
    void initTestCase() {
        QVERIFY(dir_.isValid());
        const QString spec = write("block.json", studyWith(kBlock));
        const Run r = cli({"study", "--spec", spec, "-o", dir_.filePath("rows.jsonl")});
        QVERIFY2(r.code == 0, r.err);
        for (const QByteArray& l : readAll(dir_.filePath("rows.jsonl")).trimmed().split('\n'))
            rows_.push_back(QJsonDocument::fromJson(l).object());
    }
    void scaleIsTheRockingCommands() {
        // The study's search as rocking's flags: max_g, max_g / scan_step_g points, and the
        // tolerance relative to max_g (core/study/StudyBlock.h).
        QCOMPARE(rows_.size(), kFiles.size());
        int overturned = 0;
        for (int i = 0; i < kFiles.size(); ++i) {
            const Run r = cli({"rocking", "--half-width", "0.15", "--half-height", "0.6",
                               "--record", kRecords + kFiles[i], "--critical", "--max-amplitude",
                               num(kMaxG), "--scan-points", QString::number(kMaxG / kStepG),
                               "--tolerance", num(kToleranceG / kMaxG)});
            QVERIFY2(r.code == 0, r.err);
            const QJsonObject c = QJsonDocument::fromJson(r.out).object();
            const QJsonObject& row = rows_[i];
            QCOMPARE(row["case"].toInt(), i);
            QVERIFY(row["record"].toString().endsWith(kFiles[i]));
            QCOMPARE(row["critical_peak_g"].isNull(), c["critical_amplitude_g"].isNull());
            if (row["critical_peak_g"].isNull()) continue;
            ++overturned;
            QCOMPARE(row["critical_peak_g"].toDouble(), c["critical_amplitude_g"].toDouble());
            QCOMPARE(row["runs"].toInteger(), c["critical_runs"].toInteger());
            // The ground drives the block: the intensity is the peak itself.
            QCOMPARE(row["critical_im_g"].toDouble(), row["critical_peak_g"].toDouble());
        }
        // A 0.3 x 1.2 m block (tan alpha = 0.25) overturns under each of the three records
        // below 0.8 g (the search finds 0.33 to 0.40 g): the comparison is not of nulls.
        QCOMPARE(overturned, kFiles.size());
    }
    void rowsCarryTheBlock() {
        for (const QJsonObject& row : rows_) {
            QVERIFY(!row.contains("mu") && !row.contains("tstar") && !row.contains("limit"));
            const QJsonObject b = row["block"].toObject();
            QCOMPARE(b["half_width_m"].toDouble(), 0.15);
            QCOMPARE(b["half_height_m"].toDouble(), 0.6);
            QVERIFY(b["mu"].isNull() && b["restitution"].isNull());
            QCOMPARE(b["linear"].toBool(), false);
            QCOMPARE(row["limit_im_g"].toDouble(),
                     row["record_im_g"].toDouble() * kMaxG / row["record_im_g"].toDouble());
        }
    }
    void fragilityOfTheBlock() {
        const Run f = cli({"fragility", "--results", dir_.filePath("rows.jsonl")});
        QVERIFY2(f.code == 0, f.err);
        QVERIFY2(f.out.contains("\"block\""), f.out);
        QVERIFY(!f.out.contains("\"tstar\""));
        const Run csv =
            cli({"fragility", "--results", dir_.filePath("rows.jsonl"), "--format", "csv"});
        QVERIFY2(csv.code == 0, csv.err);
        QVERIFY(csv.out.split('\n')[0].endsWith(",block"));
    }
    void anotherBlockIsAnotherStudy() {
        // The fingerprint includes the block: two one-record studies differing only in h are
        // two studies, and their rows are not merged as one.
        QStringList outs;
        for (const char* h : {"0.6", "0.7"}) {
            const QByteArray text =
                "{\"format\": \"kinstab-study\", \"version\": 1, \"records\": [{\"path\": \"" +
                (kRecords + kFiles[0]).toUtf8() +
                "\"}], \"block\": {\"half_width_m\": 0.15, \"half_height_m\": " + h +
                "}, \"search\": {\"max_g\": 0.8, \"scan_step_g\": 0.4}}";
            const QString spec = write(QString("one-%1.json").arg(h), text);
            outs << dir_.filePath(QString("one-%1.jsonl").arg(h));
            const Run r = cli({"study", "--spec", spec, "-o", outs.last()});
            QVERIFY2(r.code == 0, r.err);
        }
        const QJsonObject a = QJsonDocument::fromJson(readAll(outs[0]).trimmed()).object();
        const QJsonObject b = QJsonDocument::fromJson(readAll(outs[1]).trimmed()).object();
        QVERIFY(a["study"].toString() != b["study"].toString());
        const Run m = cli({"merge", outs[0], outs[1], "-o", "-"});
        QCOMPARE(m.code, 2);
        QVERIFY2(m.err.contains(a["study"].toString().toUtf8()), m.err);
    }
    void badBlockKeys_data() {
        QTest::addColumn<QByteArray>("members");
        QTest::addColumn<QString>("named");
        QTest::newRow("unknown key")
            << QByteArray("\"block\": {\"half_width_m\": 0.15, \"half_height_m\": 0.6, "
                          "\"width\": 0.3}")
            << "block.width";
        QTest::newRow("missing height")
            << QByteArray("\"block\": {\"half_width_m\": 0.15}") << "block.half_height_m";
        QTest::newRow("negative width")
            << QByteArray("\"block\": {\"half_width_m\": -1, \"half_height_m\": 0.6}")
            << "block.half_width_m";
        QTest::newRow("restitution")
            << QByteArray("\"block\": {\"half_width_m\": 0.15, \"half_height_m\": 0.6, "
                          "\"restitution\": 1.5}")
            << "block.restitution";
        QTest::newRow("mu") << QByteArray("\"block\": {\"half_width_m\": 0.15, "
                                          "\"half_height_m\": 0.6, \"mu\": 0}")
                            << "block.mu";
        QTest::newRow("linear") << QByteArray("\"block\": {\"half_width_m\": 0.15, "
                                              "\"half_height_m\": 0.6, \"linear\": \"yes\"}")
                                << "block.linear";
        QTest::newRow("not an object") << QByteArray("\"block\": 3") << "block";
        QTest::newRow("slab parameter")
            << (kBlock + ", \"parameters\": {\"mu\": [0.5]}") << "parameters.mu";
    }
    void badBlockKeys() {
        QFETCH(QByteArray, members);
        QFETCH(QString, named);
        const QString spec = write("bad.json", studyWith(members));
        const Run r = cli({"study", "--spec", spec, "--count"});
        QCOMPARE(r.code, 2);
        QVERIFY2(r.err.contains(named.toUtf8()), r.err);
    }
};

QTEST_GUILESS_MAIN(TestCliStudyBlock)
#include "tst_cli_study_block.moc"
