// SPDX-License-Identifier: GPL-3.0-or-later
// kinstab-cli with hostile, foreign and nonsensical input: every case is exit 2 with a
// message naming the input, the line or field and the limit, never a crash (exit -1 here), an
// internal error (exit 1) or a silent exit 0. Latin-1 header text and a UTF-8 byte-order mark
// are read. Each case reproduces one found by trying the program (kinstab issues 13 and 14).

#include "CliRun.h"

#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QtTest>

namespace {

const QString kRoot = QStringLiteral(KINSTAB_SOURCE_DIR);
const QString kPacoima = kRoot + "/resources/records/RSN77_SFERN_PUL164.AT2";
const QString kExample = kRoot + "/resources/examples/paper-16-story.json";
const QString kRecordProject = kRoot + "/resources/examples/paper-16-story-record.json";

QByteArray contents(const QString& path) {
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

void write(const QString& path, const QByteArray& bytes) {
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    QCOMPARE(f.write(bytes), bytes.size());
}

// Line 2 of the Pacoima Dam AT2 record ("San Fernando, 2/9/1971, Pacoima Dam (upper left
// abut), 164") with a station name in Latin-1 (0xE9 is é).
QByteArray latin1Record() {
    QByteArray r = contents(kPacoima);
    const qsizetype a = r.indexOf('\n') + 1, b = r.indexOf('\n', a);
    return r.left(a) + "M\xE9xico, 9/19/1985, Estaci\xF3n SCT, 90" + r.mid(b);
}

// The message of a run that must be refused: exit 2, one line naming `names`.
void refused(const Run& r, const QString& names) {
    QVERIFY2(r.code == 2, qPrintable(QString("exit %1: %2").arg(r.code).arg(r.err)));
    QVERIFY2(QString::fromUtf8(r.err).contains(names), r.err.constData());
    QVERIFY2(r.err.size() < 2000, "the message quotes only a short prefix of the input");
}

} // namespace

class TestCliHostileInput : public QObject {
    Q_OBJECT
private slots:
    void latin1RecordHeader() {
        QTemporaryDir dir;
        const QString rec = dir.filePath("mexico.AT2");
        write(rec, latin1Record());
        const Run r = cli({"record", "--file", rec});
        QVERIFY2(r.code == 0, r.err.constData());
        const QJsonObject j = QJsonDocument::fromJson(r.out).object()["record"].toObject();
        QCOMPARE(j["station"].toString(), QString::fromUtf8("Estaci\xC3\xB3n SCT"));
        const Run s = cli({"simulate", "--record", rec, "--amplitude", "0.5"});
        QVERIFY2(s.code == 0, s.err.constData());
        QVERIFY(QString::fromUtf8(s.out).contains(QString::fromUtf8("M\xC3\xA9xico")));
        // check --project with that record: the record project's file, beside the project.
        QByteArray project = contents(kRecordProject);
        project.replace("../records/RSN77_SFERN_PUL164.AT2", "mexico.AT2");
        write(dir.filePath("p.json"), project);
        const Run c = cli({"check", "--project", dir.filePath("p.json")});
        QVERIFY2(c.code == 0, c.err.constData());
    }
    void byteOrderMarks() {
        QTemporaryDir dir;
        write(dir.filePath("p.json"), "\xEF\xBB\xBF" + contents(kExample));
        const Run c = cli({"codes", "--project", dir.filePath("p.json")});
        QVERIFY2(c.code == 0, c.err.constData());
        write(dir.filePath("t.csv"), "\xEF\xBB\xBFtime,accel\n0,0.1\n0.01,0.2\n0.02,-0.1\n");
        const Run r = cli({"record", "--file", dir.filePath("t.csv")});
        QVERIFY2(r.code == 0, r.err.constData());
        const QByteArray table =
            contents(kRoot + "/resources/data/furgerson1980/table1_triplet_tests.csv");
        write(dir.filePath("f.csv"), "\xEF\xBB\xBF" + table);
        const Run f = cli({"friction", "--data", dir.filePath("f.csv")});
        QVERIFY2(f.code == 0, f.err.constData());
    }
    void badRecordFiles_data() {
        QTest::addColumn<QByteArray>("text");
        QTest::addColumn<QStringList>("extra");
        QTest::addColumn<QString>("message");
        const QByteArray head = "PEER NGA STRONG MOTION DATABASE RECORD\nX, 1/1/2000, Y, 90\n"
                                "ACCELERATION TIME SERIES IN UNITS OF G\n";
        QTest::newRow("1e308 g") << head + "NPTS= 3, DT= .01 SEC\n .1E-02 1e308 .1\n"
                                 << QStringList() << "sample 2 is 1e+308 g, beyond 100 g";
        QTest::newRow("DT of 1e300") << head + "NPTS= 3, DT= 1e300 SEC\n .1E-02 .2 .1\n"
                                     << QStringList() << "sample interval 1e+300 s is outside";
        QTest::newRow("NPTS beyond any count")
            << head + "NPTS= 99999999999999999999, DT= .01 SEC\n .1E-02 .2 .1\n"
            << QStringList()
            << "NPTS '99999999999999999999' must be a whole number from 2 to 10000000";
        QTest::newRow("channel for an AT2 file")
            << head + "NPTS= 3, DT= .01 SEC\n .1E-02 .2 .1\n"
            << QStringList{"--record-channel", "abc"}
            << "channel 'abc' was asked for, but only CSMIP V2 files have channels";
        QByteArray cosmos = contents(kRoot + "/resources/records/"
                                             "us1000hyfh_akbmrp_AKBMR--n.1000hyfh.BNZ.--.acc.V2c");
        const QByteArray formatAt = ",Format=(1E15.6)";
        QVERIFY(cosmos.contains(formatAt));
        QTest::newRow("COSMOS data line without Format=")
            << QByteArray(cosmos).replace(formatAt, "") << QStringList()
            << ":53: no Fortran data format";
        QTest::newRow("COSMOS header announcing 4e18 points")
            << QByteArray(cosmos).replace("   42000 acceleration pts",
                                          "   4000000000000000000 acceleration pts")
            << QStringList()
            << ":53: number of points '4000000000000000000': expected a whole "
               "number within the limit of 10000000";
        QTest::newRow("a 10 MB token")
            << head + "NPTS= 3, DT= .01 SEC\n .1 " + QByteArray(10'000'000, 'x') + " .1\n"
            << QStringList() << "value 2 'xxxx";
    }
    void badRecordFiles() {
        QFETCH(QByteArray, text);
        QFETCH(QStringList, extra);
        QFETCH(QString, message);
        QTemporaryDir dir;
        write(dir.filePath("bad.rec"), text);
        refused(cli(QStringList{"record", "--file", dir.filePath("bad.rec")} + extra), message);
        refused(cli(QStringList{"simulate", "--record", dir.filePath("bad.rec")} + extra), message);
    }
    void badProjects_data() {
        QTest::addColumn<QByteArray>("text");
        QTest::addColumn<QString>("message");
        QTest::newRow("50,000 nested arrays")
            << QByteArray(50'000, '[') + QByteArray(50'000, ']')
            << "arrays and objects nested more than 64 levels deep";
        QTest::newRow("number literal 1e999")
            << contents(kExample).replace("\"format\"", "\"x\": 1e999, \"format\"")
            << "number overflow parsing '1e999'";
        QByteArray named = contents(kExample); // the first "name" is the project's
        named.insert(named.indexOf("\"name\": \"") + 9, QByteArray(10'000'000, 'N'));
        QTest::newRow("10 MB project name")
            << named << "name: 10000033 characters, more than the limit of 200";
        // Cut at the NUL, the path names the shipped record: refused, not read (issue 31).
        QTest::newRow("record path with a NUL")
            << contents(kRecordProject)
                   .replace("../records/RSN77_SFERN_PUL164.AT2",
                            (kRoot + "/resources/records/RSN77_SFERN_PUL164.AT2\\u0000.x").toUtf8())
            << "excitation.record.file: the path contains a NUL character";
        // Issue 31: text that prints otherwise than it reads on the signed page 1.
        QTest::newRow("bidi override in the registration")
            << contents(kExample).replace("S 00000 (example)", "S 12345\\u202e67890")
            << "info.registration: contains U+202E (a bidirectional override) at character 8";
        QTest::newRow("ESC in the project name")
            << contents(kExample).replace("Furgerson 1980,", "Furgerson\\u001b[31m 1980,")
            << "name: contains U+001B (a control character) at character 10";
        QTest::newRow("NUL in the engineer")
            << contents(kExample).replace("A. N. Example, P.E.", "A. N.\\u0000 Example")
            << "info.engineer: contains U+0000 (NUL) at character 6";
        QByteArray lines = contents(kExample);
        lines.replace("Furgerson 1980, 16-story building", QByteArray("line\\n").repeated(30));
        QTest::newRow("30-line project name") // 150 characters: within the length limit
            << lines << "name: contains U+000A (a line break in one-line text) at character 5";
        QTest::newRow("isolate in a revision")
            << contents(kExample).replace("Issued for permit", "Issued \\u2067for\\u2069 permit")
            << "info.revisions[1].description: contains U+2067 (a bidirectional isolate) at "
               "character 8";
        QTest::newRow("BEL in the building name")
            << contents(kExample).replace("16-story office building", "16-story\\u0007")
            << "building.name: contains U+0007 (a control character) at character 9";
        QTest::newRow("201 characters of two bytes") // counted in characters, not bytes
            << contents(kExample).replace("Furgerson 1980, 16-story building",
                                          QByteArray("\xc3\xa9").repeated(201))
            << "name: 201 characters, more than the limit of 200";
    }
    void badProjects() {
        QFETCH(QByteArray, text);
        QFETCH(QString, message);
        QTemporaryDir dir;
        const QString p = dir.filePath("bad.json");
        write(p, text);
        refused(cli({"check", "--project", p}), message);
        refused(cli({"codes", "--project", p}), message);
        refused(cli({"report", "--project", p, "-o", dir.filePath("r.pdf")}), message);
        QVERIFY(!QFile::exists(dir.filePath("r.pdf")));
    }
    void nonsenseFlags() {
        refused(cli({"critical", "--frequencies", "1", "--mu", "0"}),
                "--mu 0: friction coefficient must be between 0.01 and 10");
        refused(cli({"report", "--project", kExample, "-o", ""}),
                "-o \"\": the file name is empty");
        // 20.16 s of run (tau_end of this case) every 1e-7: 2e8 rows; it once took 24 GB.
        refused(cli({"simulate", "--amplitude", "1.2", "--frequency", "1", "--history",
                     QDir::temp().filePath("kinstab-never-written.csv"), "--history-step", "1e-7"}),
                "rows, more than the limit of 2000000");
        QVERIFY(!QFile::exists(QDir::temp().filePath("kinstab-never-written.csv")));
        // Each axis under its own limit, the product of 10001 x 100 points over it.
        refused(cli({"surface", "--amplitudes", "0:10:0.001", "--frequencies", "1:100:1"}),
                "10001 amplitudes x 100 frequencies, more than the limit of 1000000 points");
        refused(cli({"simulate", "--amplitude", "1,2", "--frequency", "1"}),
                "--amplitude '1,2' is not a finite number");
    }
    // The decimal point in flags and files, whatever the locale the suite runs in (it runs
    // again under de_DE.UTF-8, see tests/CMakeLists.txt).
    void numbersInFlagsAndFiles() {
        const Run r = cli({"critical", "--frequencies", "0.5,1.125", "--mu", "0.6"});
        QVERIFY2(r.code == 0, r.err.constData());
        QVERIFY(!r.out.contains("0,5"));
        QTemporaryDir dir;
        const Run s = cli({"simulate", "--amplitude", "1.2", "--frequency", "1", "--history",
                           dir.filePath("h.csv"), "--history-step", "0.25"});
        QVERIFY2(s.code == 0, s.err.constData());
        const QList<QByteArray> rows = contents(dir.filePath("h.csv")).split('\n');
        QCOMPARE(rows.value(0), QByteArray("tau,accel_g,delta,velocity,state"));
        QCOMPARE(rows.value(2).split(',').value(0), QByteArray("0.25")); // 1 x the step
    }
};

QTEST_GUILESS_MAIN(TestCliHostileInput)
#include "tst_cli_hostile_input.moc"
