// SPDX-License-Identifier: GPL-3.0-or-later
// kill -9 at random points of `surface -o` and `report -o` over an existing good file (issue
// 14): afterwards the file is the old one or a complete new one, byte for byte, never anything
// else. The kill times are drawn from a fixed seed (reproducible) over the whole run, the
// program's start-up and its final write and rename included.

#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QRandomGenerator>
#include <QTemporaryDir>
#include <QtTest>

#include "CliRun.h"
#include "FileBytes.h"

#include <cstdlib>
#include <functional>

namespace {

constexpr int kRuns = 50; // per command

// Runs args to completion into out; returns the file and sets ms to the wall time.
QByteArray completeRun(const QStringList& args, const QString& out, qint64& ms) {
    QElapsedTimer t;
    t.start();
    const Run r = cli(args + QStringList{"-o", out});
    ms = t.elapsed();
    return r.code == 0 ? readAll(out) : QByteArray();
}

struct Tally {
    int old = 0, complete = 0, leftovers = 0;
};

// Starts args over a file holding `old`, kills it after a random delay, checks the file.
Tally killRuns(const QStringList& args, const QString& out, const QByteArray& old,
               const std::function<bool(const QByteArray&)>& complete, qint64 fullMs,
               quint32 seed) {
    QRandomGenerator random(seed);
    Tally t;
    for (int k = 0; k < kRuns; ++k) {
        writeBytes(out, old);
        QProcess p;
        p.start(KINSTAB_CLI, args + QStringList{"-o", out});
        if (!p.waitForStarted()) return {};
        // Up to 1.5× the measured run: on a busy machine a run takes longer than the measured
        // one, and the kills should reach the final write and rename too.
        const int delay = random.bounded(static_cast<int>(fullMs * 3 / 2) + 1);
        if (!p.waitForFinished(delay)) p.kill(); // SIGKILL
        p.waitForFinished(60000);
        const QByteArray now = readAll(out);
        if (now == old)
            ++t.old;
        else if (complete(now))
            ++t.complete;
        else
            qWarning("run %d killed after %d ms left %lld bytes that are neither file", k, delay,
                     static_cast<long long>(now.size()));
        // A kill -9 between creating and renaming the temporary file leaves it (nothing can
        // run after SIGKILL); count and remove it.
        const QFileInfo info(out);
        for (const QString& tmp :
             info.dir().entryList({"." + info.fileName() + ".*.tmp"}, QDir::Files | QDir::Hidden)) {
            ++t.leftovers;
            QFile::remove(info.dir().filePath(tmp));
        }
    }
    return t;
}

} // namespace

class TestCliFaults : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

    // complete: is this a whole new file (given one made by an uninterrupted run)?
    void check(const QStringList& args, const QString& name, const QByteArray& old,
               const std::function<bool(const QByteArray&, const QByteArray&)>& complete,
               quint32 seed) {
        const QString out = dir_.filePath(name);
        qint64 ms = 0;
        const QByteArray reference = completeRun(args, out, ms);
        QVERIFY(!reference.isEmpty());
        QVERIFY(complete(reference, reference) && !complete(old, reference));
        const Tally t = killRuns(
            args, out, old, [&](const QByteArray& b) { return complete(b, reference); }, ms, seed);
        qInfo("%s: %d kill -9 runs over a %lld ms run: %d left the old file, %d the new one "
              "(%d temporary files left by the kill)",
              qPrintable(args.first()), kRuns, static_cast<long long>(ms), t.old, t.complete,
              t.leftovers);
        QCOMPARE(t.old + t.complete, kRuns);
    }

private slots:
    void initTestCase() { QVERIFY(dir_.isValid()); }

    void surfaceOverGoodFile() {
        const QStringList args = {
            "surface", "--amplitudes", "0.2:1.2:0.05", "--frequencies", "1:8:0.5", "--threads",
            "1",       "--format",     "csv"};
        // The old file: a complete, different surface (a smaller grid). The CSV holds no wall
        // time, so a complete new file equals the reference byte for byte.
        const Run r =
            cli({"surface", "--amplitudes", "0.5", "--frequencies", "2", "--format", "csv"});
        QVERIFY2(r.code == 0, r.err.constData());
        check(
            args, "surface.csv", r.out,
            [](const QByteArray& b, const QByteArray& ref) { return b == ref; }, 1401);
    }

    void reportOverGoodFile() {
        const QString project =
            QStringLiteral(KINSTAB_SOURCE_DIR "/resources/examples/paper-16-story.json");
        const QStringList args = {"report", "--project", project, "--figure-grid", "5"};
        // The old file: a complete report of the same project on letter paper.
        const QString old = dir_.filePath("old.pdf");
        QCOMPARE(cli(args + QStringList{"--page", "letter", "-o", old}).code, 0);
        // The report's title block holds its creation time, so a complete new file is one of
        // the reference's size (±64 bytes) that ends the PDF (%%EOF) with A4 pages: letter
        // pages would be the old file.
        const auto complete = [&](const QByteArray& b, const QByteArray& ref) {
            return std::abs(b.size() - ref.size()) <= 64 && b.startsWith("%PDF-") &&
                   b.trimmed().endsWith("%%EOF") && b.contains("/MediaBox [0 0 595");
        };
        check(args, "report.pdf", readAll(old), complete, 1402);
    }
};

QTEST_GUILESS_MAIN(TestCliFaults)
#include "tst_cli_faults.moc"
