// SPDX-License-Identifier: GPL-3.0-or-later
// Interrupted and resumed outputs of study and merge (issue 31), run as a user or a scheduler
// would stop them:
//  - SIGTERM (kill, scancel, a Slurm time limit) and SIGINT of `study -o` and `merge -o` leave
//    nothing behind: no output, no temporary file;
//  - kill -9 of `study -o` leaves its temporary file, and `study --resume` completes it to the
//    bytes an uninterrupted run writes; SIGTERM of a --resume run keeps it for the next one;
//  - a symlink given as -o is written through, as for every other output;
//  - merge reads more shards than the process may open at once (RLIMIT_NOFILE lowered).

#include "CliRun.h"
#include "FileBytes.h"

#include <sys/resource.h>
#include <sys/stat.h>

#include <QDir>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QProcess>
#include <QTemporaryDir>
#include <QThread>
#include <QtTest>

#include <csignal>

namespace {

// 144 cases, some seconds on one thread: a run a signal reaches in its middle.
QByteArray slowStudy() {
    return "{\"format\": \"kinstab-study\", \"version\": 1, \"records\": [{\"path\": "
           "\"" KINSTAB_SOURCE_DIR
           "/resources/records\", \"include\": [\"*.AT2\"], \"exclude\": [\"*UP*\", \"*DWN*\"]}],"
           " \"parameters\": {\"mu\": \"0.3:0.85:0.05\", \"floor_filter\": {\"periods_s\": [0.5],"
           " \"include_ground\": true}},"
           " \"search\": {\"max_g\": 3, \"scan_step_g\": 0.01, \"tolerance_g\": 1e-6}}";
}

// The temporary files the atomic writer leaves beside `out` (".NAME.RANDOM.tmp").
QStringList temporaries(const QString& out) {
    const QFileInfo info(out);
    return info.dir().entryList({"." + info.fileName() + ".*.tmp"}, QDir::Files | QDir::Hidden);
}

// Waits up to 20 s for a temporary file of `out` with at least `bytes` bytes.
bool waitForTemporary(const QString& out, qint64 bytes) {
    QElapsedTimer t;
    t.start();
    while (t.elapsed() < 20000) {
        for (const QString& name : temporaries(out))
            if (QFileInfo(QFileInfo(out).dir().filePath(name)).size() >= bytes) return true;
        QThread::msleep(5);
    }
    return false;
}

// Sends `signal` to p once out's temporary file holds `bytes` bytes; returns the ms from the
// signal to the process's end (-1 if it did not end).
qint64 signalMidWrite(QProcess& p, const QString& out, qint64 bytes, int signal) {
    if (!p.waitForStarted() || !waitForTemporary(out, bytes)) return -1;
    QElapsedTimer t;
    t.start();
    ::kill(static_cast<pid_t>(p.processId()), signal);
    return p.waitForFinished(30000) ? t.elapsed() : -1;
}

} // namespace

class TestCliInterrupt : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;
    QString spec_;
    QByteArray whole_; // the slow study's rows, uninterrupted

private slots:
    void initTestCase() {
        QVERIFY(dir_.isValid());
        spec_ = dir_.filePath("slow.json");
        writeBytes(spec_, slowStudy());
        const Run r = cli({"study", "--spec", spec_, "--threads", "2"});
        QVERIFY2(r.code == 0, r.err.constData());
        whole_ = r.out;
        QCOMPARE(whole_.count('\n'), 144); // 12 mu x 2 drivers x 6 records
    }

    void signalsLeaveNoStudyOutput_data() {
        QTest::addColumn<int>("signal");
        QTest::newRow("SIGTERM") << int(SIGTERM);
        QTest::newRow("SIGINT") << int(SIGINT);
    }
    void signalsLeaveNoStudyOutput() {
        QFETCH(int, signal);
        const QString out = dir_.filePath(QString("study-%1.jsonl").arg(signal));
        QProcess p;
        p.start(KINSTAB_CLI, {"study", "--spec", spec_, "--threads", "1", "-o", out});
        const qint64 ms = signalMidWrite(p, out, 1, signal); // once the first rows are in
        QVERIFY(ms >= 0);
        qInfo("study -o: the signal to the end of the process: %lld ms", ms);
        QCOMPARE(p.exitStatus(), QProcess::CrashExit); // ended by the signal, as without handler
        QCOMPARE(temporaries(out), QStringList());
        QVERIFY(!QFileInfo::exists(out));
    }

    void sigtermLeavesNoMergeOutput() {
        // A shard that is a FIFO nobody writes yet: the merge waits in it, its output begun.
        const QString fifo = dir_.filePath("shard.fifo"), out = dir_.filePath("merged.jsonl");
        QCOMPARE(::mkfifo(fifo.toLocal8Bit().constData(), 0600), 0);
        QProcess p;
        p.start(KINSTAB_CLI, {"merge", fifo, "-o", out});
        const qint64 ms = signalMidWrite(p, out, 0, SIGTERM);
        QVERIFY(ms >= 0);
        qInfo("merge -o: SIGTERM to the end of the process: %lld ms", ms);
        QCOMPARE(temporaries(out), QStringList());
        QVERIFY(!QFileInfo::exists(out));
    }

    void killedStudyResumesToTheSameBytes() {
        const QString out = dir_.filePath("resumed.jsonl");
        QProcess p;
        p.start(KINSTAB_CLI, {"study", "--spec", spec_, "--threads", "1", "-o", out});
        QVERIFY(signalMidWrite(p, out, 1, SIGKILL) >= 0);
        const QStringList left = temporaries(out);
        QCOMPARE(left.size(), 1); // kill -9 cannot be caught: the rows so far stay
        const QByteArray partial = readAll(QFileInfo(out).dir().filePath(left[0]));
        QVERIFY(whole_.startsWith(partial.left(partial.lastIndexOf('\n') + 1)));
        const Run r = cli({"study", "--spec", spec_, "--threads", "2", "--resume", "-o", out});
        QVERIFY2(r.code == 0, r.err.constData());
        QVERIFY2(r.err.contains("resuming"), r.err.constData());
        QCOMPARE(readAll(out), whole_);
        QCOMPARE(temporaries(out), QStringList());
    }

    void sigtermOfAResumableRunKeepsItsRows() {
        const QString out = dir_.filePath("kept.jsonl");
        QProcess p;
        p.start(KINSTAB_CLI, {"study", "--spec", spec_, "--threads", "1", "--resume", "-o", out});
        QVERIFY(signalMidWrite(p, out, 1, SIGTERM) >= 0);
        QCOMPARE(temporaries(out).size(), 1);
        QVERIFY(!QFileInfo::exists(out));
        const Run r = cli({"study", "--spec", spec_, "--threads", "2", "--resume", "-o", out});
        QVERIFY2(r.code == 0 && r.err.contains("resuming"), r.err.constData());
        QCOMPARE(readAll(out), whole_);
        QCOMPARE(temporaries(out), QStringList());
    }

    void anotherStudysTemporaryIsLeftAlone() {
        const QString out = dir_.filePath("foreign.jsonl");
        const QString foreign = dir_.filePath(".foreign.jsonl.abcdefghijkl.tmp");
        QByteArray other = whole_.left(whole_.indexOf('\n') + 1);
        other.replace("\"mu\":0.3", "\"mu\":0.35");
        const qsizetype at = other.indexOf("\"study\":\"") + 9;
        other[at] = other[at] == '0' ? '1' : '0'; // another fingerprint
        writeBytes(foreign, other);
        const Run r = cli({"study", "--spec", spec_, "--threads", "2", "--resume", "-o", out});
        QVERIFY2(r.code == 0 && !r.err.contains("resuming"), r.err.constData());
        QCOMPARE(readAll(out), whole_);
        QCOMPARE(readAll(foreign), other);
        QVERIFY(QFile::remove(foreign));
        QCOMPARE(cli({"study", "--spec", spec_, "--resume"}).code, 2); // needs -o FILE
    }

    void symlinkOutputIsWrittenThrough() {
        const QString target = dir_.filePath("target.jsonl"), link = dir_.filePath("link.jsonl");
        const QString small = KINSTAB_TEST_DATA "/study/small-study.json";
        writeBytes(target, "old\n");
        QVERIFY(QFile::link(target, link));
        Run r = cli({"study", "--spec", small, "-o", link});
        QVERIFY2(r.code == 0, r.err.constData());
        QVERIFY(QFileInfo(link).isSymLink());
        const QByteArray rows = readAll(target);
        QCOMPARE(rows.count('\n'), 12);
        writeBytes(dir_.filePath("rows.jsonl"), rows);
        writeBytes(target, "old\n");
        r = cli({"merge", dir_.filePath("rows.jsonl"), "-o", link});
        QVERIFY2(r.code == 0, r.err.constData());
        QVERIFY(QFileInfo(link).isSymLink());
        QCOMPARE(readAll(target), rows);
    }

    void mergeReadsMoreShardsThanItMayOpen() {
        // The small study's 12 rows in 200 shards, most of them empty, merged by a process that
        // may open 64 files (the list file, the output and the standard streams among them).
        const QByteArray rows = [] {
            return cli({"study", "--spec", KINSTAB_TEST_DATA "/study/small-study.json"}).out;
        }();
        const QList<QByteArray> lines = rows.trimmed().split('\n');
        QCOMPARE(lines.size(), 12);
        QDir().mkpath(dir_.filePath("many"));
        QByteArray list;
        for (int k = 0; k < 200; ++k) {
            const QString shard = dir_.filePath(QString("many/s%1.jsonl").arg(k));
            writeBytes(shard, k < lines.size() ? lines[k] + "\n" : QByteArray());
            list += shard.toUtf8() + "\n";
        }
        writeBytes(dir_.filePath("many.txt"), list);
        QProcess p;
        p.setChildProcessModifier([] {
            const rlimit low{64, 64};
            ::setrlimit(RLIMIT_NOFILE, &low);
        });
        const QString out = dir_.filePath("many.jsonl");
        QElapsedTimer t;
        t.start();
        p.start(KINSTAB_CLI, {"merge", "--list", dir_.filePath("many.txt"), "-o", out});
        QVERIFY(p.waitForFinished(60000));
        qInfo("merge of 200 shards with 64 descriptors: %lld ms", t.elapsed());
        QVERIFY2(p.exitCode() == 0, p.readAllStandardError().constData());
        QCOMPARE(readAll(out), rows);
    }
};

QTEST_GUILESS_MAIN(TestCliInterrupt)
#include "tst_cli_interrupt.moc"
