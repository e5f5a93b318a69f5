// SPDX-License-Identifier: GPL-3.0-or-later
// Where kinstab-cli's outputs go and what a failed write leaves behind (issue 14): -o "" and
// a missing folder are bad input (exit 2); -o - is stdout; a device or FIFO target is written
// straight through, never replaced; a symlink at the old fixed temporary name is not
// followed; a full device or a full stdout is exit 3 with the reason, and the old file stays.
// The full-disk case needs root and a tmpfs mount; it is skipped with a message otherwise.

#include <QDir>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

#include "CliRun.h"
#include "FileBytes.h"

#include <sys/mount.h>
#include <sys/stat.h>
#include <unistd.h>

namespace {

// CSV: no wall time in it, so two runs give the same bytes.
const QStringList kSurface = {"surface", "--amplitudes", "0.3,0.6", "--frequencies",
                              "2,4",     "--format",     "csv"};
const QString kProject =
    QStringLiteral(KINSTAB_SOURCE_DIR "/resources/examples/paper-16-story.json");

bool isCharDevice(const char* path) {
    struct stat st {};
    return ::stat(path, &st) == 0 && S_ISCHR(st.st_mode);
}

// Runs the CLI with stdout going to a file (or device) instead of a pipe.
Run cliToFile(const QStringList& args, const QString& stdoutFile) {
    QProcess p;
    p.setStandardOutputFile(stdoutFile, QIODevice::Append);
    p.start(KINSTAB_CLI, args);
    if (!p.waitForFinished(300000)) p.kill();
    return {
        p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1, {}, p.readAllStandardError()};
}

} // namespace

class TestCliOutputs : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;
    QByteArray surfaceCsv_; // what kSurface prints: the reference for a complete file

private slots:
    void initTestCase() {
        QVERIFY(dir_.isValid());
        const Run r = cli(kSurface);
        QVERIFY2(r.code == 0, r.err.constData());
        QVERIFY(r.out.startsWith("amplitude") || r.out.contains(','));
        surfaceCsv_ = r.out;
    }

    void emptyNameIsBadInput() {
        for (const QStringList& args :
             {kSurface + QStringList{"-o", ""},
              QStringList{"report", "--project", kProject, "-o", ""},
              QStringList{"simulate", "--amplitude", "0.5", "--frequency", "3", "--history", ""}}) {
            const Run r = cli(args);
            QCOMPARE(r.code, 2);
            QVERIFY2(r.err.contains("file name is empty"), r.err.constData());
        }
    }

    void missingFolderIsBadInput() {
        const Run r = cli(kSurface + QStringList{"-o", dir_.filePath("no/such/folder/s.csv")});
        QCOMPARE(r.code, 2);
        QVERIFY2(r.err.contains("does not exist"), r.err.constData());
    }

    void dashIsStdout() {
        const Run r = cli(kSurface + QStringList{"-o", "-"});
        QCOMPARE(r.code, 0);
        QCOMPARE(r.out, surfaceCsv_);
        QVERIFY(!QFile::exists("-"));
    }

    void reportToStdout() {
        const Run r = cli({"report", "--project", kProject, "--figure-grid", "5", "-o", "-"});
        QVERIFY2(r.code == 0, r.err.constData());
        QVERIFY(r.out.startsWith("%PDF-"));
        QVERIFY(r.out.trimmed().endsWith("%%EOF"));
        // The summary goes to stderr (after any Qt start-up notice).
        QVERIFY(QJsonDocument::fromJson(r.err.mid(r.err.indexOf('{'))).object().contains("pages"));
    }

    void replacesOldFileWhole() {
        const QString out = dir_.filePath("replace.csv");
        writeBytes(out, "old contents\n");
        QFile::setPermissions(out, QFileDevice::ReadOwner | QFileDevice::WriteOwner);
        const Run r = cli(kSurface + QStringList{"-o", out});
        QCOMPARE(r.code, 0);
        QCOMPARE(readAll(out), surfaceCsv_);
        QCOMPARE(QFile::permissions(out) & 0x0777, // the old file's mode is kept
                 QFileDevice::ReadUser | QFileDevice::WriteUser);
        QCOMPARE(QDir(dir_.path()).entryList({"*replace*"}, QDir::Files | QDir::Hidden),
                 QStringList{"replace.csv"}); // no temporary file left
    }

    // The old writer used OUT.part: a symlink planted there sent the output to its target.
    void plantedSymlinkIsNotFollowed() {
        QTemporaryDir d;
        const QString victim = d.filePath("victim.txt");
        writeBytes(victim, "precious\n");
        const QString out = d.filePath("s.csv");
        QVERIFY(QFile::link(victim, out + ".part"));
        const Run r = cli(kSurface + QStringList{"-o", out});
        QCOMPARE(r.code, 0);
        QCOMPARE(readAll(victim), QByteArray("precious\n"));
        QCOMPARE(readAll(out), surfaceCsv_);
        QVERIFY(QFileInfo(out + ".part").isSymLink());
        QCOMPARE(QDir(d.path()).entryList(QDir::Files | QDir::Hidden | QDir::System).size(), 3);
    }

    // -o LINK where LINK is a symlink the user made: the file it names is replaced, the link kept.
    void targetSymlinkKeepsLink() {
        QTemporaryDir d;
        const QString real = d.filePath("real.csv");
        writeBytes(real, "old\n");
        const QString link = d.filePath("link.csv");
        QVERIFY(QFile::link(real, link));
        QCOMPARE(cli(kSurface + QStringList{"-o", link}).code, 0);
        QVERIFY(QFileInfo(link).isSymLink());
        QCOMPARE(readAll(real), surfaceCsv_);
    }

    // As root the old writer renamed a regular file over /dev/null; now it writes through.
    void devNullStaysADevice() {
        const Run r = cli(kSurface + QStringList{"-o", "/dev/null"});
        QCOMPARE(r.code, 0);
        QVERIFY(isCharDevice("/dev/null"));
    }

    void devFullIsAFailedWrite() {
        if (!QFile::exists("/dev/full")) QSKIP("no /dev/full here");
        const Run r = cli(kSurface + QStringList{"-o", "/dev/full"});
        QCOMPARE(r.code, 3);
        QVERIFY2(r.err.contains("cannot write /dev/full: No space left on device"),
                 r.err.constData());
        QVERIFY(isCharDevice("/dev/full"));
    }

    void fullStdoutIsAFailedWrite() {
        if (!QFile::exists("/dev/full")) QSKIP("no /dev/full here");
        for (const QStringList& args : {kSurface, kSurface + QStringList{"-o", "-"},
                                        QStringList{"check", "--project", kProject}}) {
            const Run r = cliToFile(args, "/dev/full");
            QCOMPARE(r.code, 3);
            QVERIFY2(r.err.contains("cannot write standard output: No space left on device"),
                     r.err.constData());
        }
    }

    void fifoIsWrittenThrough() {
        const QString fifo = dir_.filePath("fifo");
        QCOMPARE(::mkfifo(QFile::encodeName(fifo).constData(), 0600), 0);
        QProcess reader; // the FIFO's other end
        reader.start("cat", {fifo});
        QVERIFY(reader.waitForStarted());
        const Run r = cli(kSurface + QStringList{"-o", fifo});
        QCOMPARE(r.code, 0);
        QVERIFY(reader.waitForFinished(60000));
        QCOMPARE(reader.readAllStandardOutput(), surfaceCsv_);
        QVERIFY(QFileInfo(fifo).exists() && !QFileInfo(fifo).isFile());
    }

    // A disk that fills up during the write: exit 3, the reason, the old report intact and no
    // temporary file left. Root only: a 512 KB tmpfs mounted in a temporary folder.
    void fullDiskKeepsOldFile() {
        if (::geteuid() != 0) QSKIP("full-disk test needs root (mount -t tmpfs); skipped");
        QTemporaryDir d;
        const QByteArray mountPoint = QFile::encodeName(d.path());
        if (::mount("tmpfs", mountPoint.constData(), "tmpfs", 0, "size=512k") != 0)
            QSKIP("mount -t tmpfs not permitted here (container?); full-disk test skipped");
        const QString out = d.filePath("report.pdf");
        const QByteArray old = "%PDF-1.4 the good old report\n";
        writeBytes(out, old);
        writeBytes(d.filePath("filler"), QByteArray(400 * 1024, 'x')); // leaves < 112 KB free
        const Run r = cli({"report", "--project", kProject, "--figure-grid", "5", "-o", out});
        const QByteArray after = readAll(out);
        const QStringList left = QDir(d.path()).entryList(QDir::Files | QDir::Hidden);
        ::umount(mountPoint.constData());
        QCOMPARE(r.code, 3);
        QVERIFY2(r.err.contains("No space left on device"), r.err.constData());
        QCOMPARE(after, old);
        QCOMPARE(left, (QStringList{"filler", "report.pdf"}));
    }
};

QTEST_GUILESS_MAIN(TestCliOutputs)
#include "tst_cli_outputs.moc"
