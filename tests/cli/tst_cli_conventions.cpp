// SPDX-License-Identifier: GPL-3.0-or-later
// Command-line conventions of both executables (docs/user-guide.md, "The command line"):
// --version, --help and COMMAND --help / -h exit 0 and print to stdout; `kinstab --help` and
// `kinstab --version` need no display; every JSON output names the kinstab version; the exit
// codes (0 done, 2 bad input, 3 an output not written, 4 no finite model result, 1 a bug) are
// those --help, the man page and README name (issue 31; tst_exit_codes maps the failures).

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcessEnvironment>
#include <QRegularExpression>
#include <QtTest>

#include "CliRun.h"

namespace {
const QString kExample = KINSTAB_SOURCE_DIR "/resources/examples/paper-16-story.json";

// The command names the overview lists, in its order.
QStringList overviewCommands() {
    const Run r = cli({"--help"});
    QStringList names;
    bool inList = false;
    for (const QByteArray& line : r.out.split('\n')) {
        if (line == "commands:") {
            inList = true;
            continue;
        }
        if (inList && line.isEmpty()) break;
        if (inList) names << QString::fromUtf8(line).simplified().section(' ', 0, 0);
    }
    return names;
}

// The GUI executable, built beside kinstab-cli.
QString guiProgram() {
    return QFileInfo(QStringLiteral(KINSTAB_CLI)).dir().filePath(QStringLiteral("kinstab"));
}
} // namespace

class TestCliConventions : public QObject {
    Q_OBJECT
private slots:
    void version() {
        const Run r = cli({"--version"});
        QCOMPARE(r.code, 0);
        QVERIFY(r.out.startsWith("kinstab-cli " KINSTAB_VERSION "\n"));
        QVERIFY(r.out.contains("GPL-3.0-or-later"));
    }
    void overviewListsEveryCommand() {
        QCOMPARE(overviewCommands(),
                 QStringList({"simulate", "surface", "critical", "codes", "check", "report",
                              "record", "friction", "precision", "bench", "floors", "study",
                              "merge", "fragility", "risk", "rocking", "rocking-map"}));
        QCOMPARE(cli({"-h"}).code, 0);
        QCOMPARE(cli({}).code, 2); // no command is bad input, with the overview on stdout
    }
    void commandHelp_data() {
        QTest::addColumn<QString>("command");
        QTest::addColumn<QString>("flag");
        for (const QString& c : overviewCommands())
            for (const char* flag : {"--help", "-h"})
                QTest::newRow(qPrintable(c + " " + flag)) << c << QString(flag);
    }
    void commandHelp() {
        QFETCH(QString, command);
        QFETCH(QString, flag);
        // Help wins over any other flag, even one that would be bad input.
        const Run r = cli({command, "--mu", "-1", flag});
        QCOMPARE(r.code, 0);
        QVERIFY2(r.out.startsWith(("usage: kinstab-cli " + command + " ").toUtf8()), r.out);
        QVERIFY(r.err.isEmpty());
    }
    void manPageNamesEveryCommand() {
        // docs/man/kinstab-cli.1.in is written by hand: it must not fall behind the program.
        QFile f(QStringLiteral(KINSTAB_SOURCE_DIR "/docs/man/kinstab-cli.1.in"));
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QByteArray man = f.readAll();
        for (const QString& c : overviewCommands())
            QVERIFY2(man.contains("\n.B " + c.toUtf8() + "\n"), qPrintable(c));
    }
    void exitCodesAgreeEverywhere() {
        const QByteArray help = cli({"--help"}).out.simplified();
        for (const char* code : {"0 success", "2 bad input", "3 an output could not be written",
                                 "4 the model gave no finite result", "1 a bug in kinstab"})
            QVERIFY2(help.contains(code), code);
        QFile man(QStringLiteral(KINSTAB_SOURCE_DIR "/docs/man/kinstab-cli.1.in"));
        QVERIFY(man.open(QIODevice::ReadOnly));
        const QByteArray status = man.readAll().split('\n').join(' ');
        for (const char* code :
             {".B 0 success", ".B 1 a bug in kinstab", ".B 2 bad input",
              ".B 3 an output could not be written", ".B 4 the model gave no finite result"})
            QVERIFY2(status.contains(code), code);
        QFile readme(QStringLiteral(KINSTAB_SOURCE_DIR "/README.md"));
        QVERIFY(readme.open(QIODevice::ReadOnly));
        const QByteArray text = readme.readAll().simplified();
        for (const char* code : {"0 done", "2 bad input", "3 an output could not be written",
                                 "4 the model gave no finite result", "1 a bug"})
            QVERIFY2(text.contains(code), code);
    }
    void helpNamesUnitsAndDefaults() {
        // The model flags carry the paper's defaults (Furgerson 1980, ch. IV: mu = 0.6,
        // t* = 0.099 s for the 7 5/8 in wall) and their units.
        const QString s = QString::fromUtf8(cli({"surface", "--help"}).out);
        for (const char* line : {"--mu M", "[0.6]", "--tstar S", "s [0.099]", "--amplitudes LIST",
                                 "peak accelerations, g", "Hz"})
            QVERIFY2(s.contains(line), line);
    }
    void everyFlagInHelpIsAccepted_data() {
        QTest::addColumn<QString>("command");
        for (const QString& c : overviewCommands())
            QTest::newRow(qPrintable(c)) << c;
    }
    void everyFlagInHelpIsAccepted() {
        // A flag the help documents must not be an unknown flag to the command itself.
        QFETCH(QString, command);
        const QString s = QString::fromUtf8(cli({command, "--help"}).out);
        const QRegularExpression flagRe(QStringLiteral("(?<![\\w-])--([a-z][a-z0-9-]*)"));
        QStringList flags;
        for (auto m = flagRe.globalMatch(s); m.hasNext();)
            flags << m.next().captured(1);
        flags.removeDuplicates();
        QVERIFY(!flags.isEmpty());
        for (const QString& f : flags) {
            if (f == "help" || f == "version") continue;
            // A known flag takes "1" (or, a switch, leaves it as a stray argument) and the
            // parser stops at the sentinel after it, before any work is done.
            const Run r = cli({command, "--" + f, "1", "--zz-sentinel"});
            QCOMPARE(r.code, 2);
            QVERIFY2(r.err.contains("unknown flag '--zz-sentinel'") ||
                         r.err.contains("unexpected argument '1'"),
                     qPrintable(command + " --" + f + ": " + r.err));
        }
    }
    void jsonNamesTheVersion_data() {
        QTest::addColumn<QStringList>("args");
        QTest::newRow("simulate") << QStringList{"simulate", "--amplitude", "0.5", "--frequency",
                                                 "1"};
        QTest::newRow("surface") << QStringList{"surface", "--amplitudes", "0.5", "--frequencies",
                                                "1"};
        QTest::newRow("critical") << QStringList{
            "critical", "--frequencies", "5", "--max-amplitude", "2", "--scan-step", "0.1"};
        QTest::newRow("codes") << QStringList{"codes", "--project", kExample};
        QTest::newRow("check") << QStringList{"check", "--project", kExample};
        // The planar bench dumped its object itself and wrote no version (fixed in issue 36).
        QTest::newRow("bench-planar")
            << QStringList{"bench", "--model",       "planar", "--fy",      "1", "--amplitudes",
                           "0.8",   "--frequencies", "1",      "--repeats", "1"};
        QTest::newRow("risk") << QStringList{
            "risk",
            "--hazard",
            KINSTAB_SOURCE_DIR "/resources/examples/hazard-second-order.csv",
            "--median",
            "1",
            "--beta",
            "0.5"};
    }
    void jsonNamesTheVersion() {
        QFETCH(QStringList, args);
        const Run r = cli(args);
        QCOMPARE(r.code, 0);
        const QJsonObject j = QJsonDocument::fromJson(r.out).object();
        QCOMPARE(j["kinstab_version"].toString(), QStringLiteral(KINSTAB_VERSION));
    }
    void guiHelpAndVersionWithoutDisplay() {
        // No DISPLAY, no offscreen platform: a QApplication could not start here.
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.remove("DISPLAY");
        env.remove("WAYLAND_DISPLAY");
        env.remove("QT_QPA_PLATFORM");
        for (const char* flag : {"--help", "--version"}) {
            QProcess p;
            p.setProcessEnvironment(env);
            p.start(guiProgram(), {flag});
            QVERIFY2(p.waitForFinished(60000), flag);
            QCOMPARE(p.exitStatus(), QProcess::NormalExit);
            QCOMPARE(p.exitCode(), 0);
            const QByteArray out = p.readAllStandardOutput();
            QVERIFY2(out.contains(flag == QByteArray("--help") ? "--screenshot" : KINSTAB_VERSION),
                     out);
        }
    }
};

QTEST_GUILESS_MAIN(TestCliConventions)
#include "tst_cli_conventions.moc"
