// SPDX-License-Identifier: GPL-3.0-or-later
// kinstab-cli on a terminal (issue 35): a progress line on stderr while it is a terminal and
// nothing when it is piped; one line on Ctrl+C and the signal's exit status; the wall width in
// millimetres beside inches; a warning for an amplitude that looks like m/s²; "did you mean"
// for misspelt commands and flags, and the commands a flag of another command belongs to.

#include "CliRun.h"

#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

#include <csignal>

namespace {

// A planar surface long enough for the progress line (first drawn after half a second): 41 × 51
// points at about 600 to 2000 a second on one thread of the 2-core test machine: 1 to 3 s.
const QStringList kLongSurface{
    "surface",       "--model",       "planar",     "--fy",      "2", "--amplitudes",
    "0.5:1.5:0.025", "--frequencies", "0.5:3:0.05", "--threads", "1"};
// Five times as many points for Ctrl+C, which must come while it runs, after the handler is in.
const QStringList kLongerSurface{
    "surface",      "--model",       "planar",      "--fy",      "2", "--amplitudes",
    "0.5:1.5:0.01", "--frequencies", "0.5:3:0.025", "--threads", "1"};

QString shellQuoted(const QStringList& args) {
    QStringList q;
    for (const QString& a : args)
        q << "'" + a + "'";
    return q.join(' ');
}

} // namespace

class TestCliTerminal : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

private slots:
    void progressOnATerminalOnly() {
        if (QStandardPaths::findExecutable("script").isEmpty())
            QSKIP("script (util-linux) missing");
        const QString out = dir_.filePath("s.json");
        // script(1) gives the program a pseudo-terminal: stderr is a terminal there.
        const Run tty = run(
            "script",
            {"-qec", shellQuoted(QStringList{KINSTAB_CLI} + kLongSurface + QStringList{"-o", out}),
             "/dev/null"});
        QCOMPARE(tty.code, 0);
        const QString shown = QString::fromUtf8(tty.out);
        QVERIFY2(shown.contains(QRegularExpression(
                     R"(surface: \d+/2091 points \(\d+ %\), \d+/s, \d+:\d\d left)")),
                 qPrintable(shown));
        QVERIFY(shown.endsWith("\r\x1b[K")); // wiped: the prompt comes back on a clean line
        // Piped: only the result, no progress.
        const Run piped = cli(kLongSurface + QStringList{"-o", out});
        QCOMPARE(piped.code, 0);
        QCOMPARE(piped.err, QByteArray());
    }

    void ctrlCSaysSoInOneLine() {
        QProcess p;
        p.start(KINSTAB_CLI, kLongerSurface + QStringList{"-o", dir_.filePath("c.json")});
        QVERIFY(p.waitForStarted());
        QTest::qWait(1500); // the handler is installed once the flags are read, at start-up
        ::kill(static_cast<pid_t>(p.processId()), SIGINT);
        QVERIFY(p.waitForFinished(30000));
        QCOMPARE(p.exitStatus(), QProcess::CrashExit); // ended by the signal: 130 in a shell
        QCOMPARE(p.readAllStandardError(),
                 QByteArray("kinstab-cli surface: interrupted (SIGINT)\n"));
        QVERIFY(!QFile::exists(dir_.filePath("c.json")));
    }

    void wallWidthInMillimetres() {
        // 193.675 mm = 7.625 in exactly: the same t* either way.
        const Run mm = cli(
            {"simulate", "--amplitude", "0.9", "--frequency", "1", "--wall-width-mm", "193.675"});
        const Run in =
            cli({"simulate", "--amplitude", "0.9", "--frequency", "1", "--wall-width-in", "7.625"});
        QCOMPARE(mm.code, 0);
        const QJsonObject a = QJsonDocument::fromJson(mm.out).object();
        const QJsonObject b = QJsonDocument::fromJson(in.out).object();
        QCOMPARE(a.value("tstar").toDouble(), b.value("tstar").toDouble());
        const Run both = cli({"simulate", "--amplitude", "0.9", "--frequency", "1",
                              "--wall-width-mm", "190", "--wall-width-in", "7.5"});
        QCOMPARE(both.code, 2);
        QVERIFY2(both.err.contains("--wall-width-in and --wall-width-mm exclude each other"),
                 both.err.constData());
        const Run tooThin =
            cli({"simulate", "--amplitude", "0.9", "--frequency", "1", "--wall-width-mm", "0.1"});
        QCOMPARE(tooThin.code, 2);
        QVERIFY(tooThin.err.contains("--wall-width-mm 0.1"));
    }

    void amplitudeThatLooksLikeMetresPerSecondSquared() {
        const Run r = cli({"simulate", "--amplitude", "9.81", "--frequency", "1"});
        QCOMPARE(r.code, 0); // a warning, not a refusal
        QVERIFY2(r.err.contains("warning: --amplitude 9.81 g is above 4 g"), r.err.constData());
        QVERIFY(r.err.contains("m/s²"));
        const Run fine = cli({"simulate", "--amplitude", "1.2", "--frequency", "1"});
        QCOMPARE(fine.err, QByteArray());
        // A grid reaching past 4 g is a study's choice; one wholly above it is not.
        QCOMPARE(cli({"surface", "--amplitudes", "1,6", "--frequencies", "1"}).err, QByteArray());
        QVERIFY(cli({"surface", "--amplitudes", "5,10", "--frequencies", "1"})
                    .err.contains("warning: --amplitudes 5 g"));
    }

    void didYouMean() {
        const Run command = cli({"chek", "--project", "x.json"});
        QCOMPARE(command.code, 2);
        QVERIFY2(
            command.err.startsWith("kinstab-cli: unknown command 'chek' (did you mean 'check'?)"),
            command.err.constData());
        const Run flag = cli({"simulate", "--amplitdue", "1", "--frequency", "1"});
        QCOMPARE(flag.code, 2);
        QVERIFY2(flag.err.contains("unknown flag '--amplitdue' (did you mean --amplitude?)"),
                 flag.err.constData());
        // A flag of other commands, too far from any of this one's.
        const Run other = cli({"codes", "--frequencies", "1"});
        QCOMPARE(other.code, 2);
        QVERIFY2(other.err.contains("unknown flag '--frequencies' (a flag of surface, critical"),
                 other.err.constData());
    }

    void manualPageInTheBuildTree() {
        // The usage names it, and the configured page is where it says.
        QVERIFY(cli({"--help"}).out.contains("man -l\nbuild/packaging/kinstab-cli.1"));
        QVERIFY(QFile::exists(QStringLiteral(KINSTAB_CLI).section('/', 0, -3) +
                              "/packaging/kinstab-cli.1"));
    }
};

QTEST_GUILESS_MAIN(TestCliTerminal)
#include "tst_cli_terminal.moc"
