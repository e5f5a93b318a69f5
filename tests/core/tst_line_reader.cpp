// SPDX-License-Identifier: GPL-3.0-or-later
// core/base/LineReader: the lines std::getline would give, for every chunk size (lines across
// chunk boundaries), a last line without '\n'; a line over the limit refused before it is held
// whole; a read error (/proc/self/mem at address 0: EIO) an error, not the end of the file; a
// released descriptor reopened where reading stopped, and a file replaced meanwhile refused.

#include "core/base/LineReader.h"

#include <QRandomGenerator>
#include <QTemporaryDir>
#include <QtTest>

#include <cstdio>
#include <fstream>
#include <sstream>

using namespace kinstab;

namespace {

void writeText(const std::string& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
}

std::vector<std::string> linesOf(const std::string& path, std::size_t chunk, bool suspend) {
    LineReader in(path, 1000, chunk);
    std::vector<std::string> lines;
    for (std::string line; in.next(line);) {
        lines.push_back(line);
        if (suspend) in.suspend(); // reopened by the next read
    }
    return lines;
}

} // namespace

class TestLineReader : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

private slots:
    void linesAsGetlineGivesThem() {
        QRandomGenerator random(7);
        std::string text;
        for (int i = 0; i < 200; ++i)
            text += std::string(random.bounded(120), static_cast<char>('a' + i % 26)) + "\n";
        text += "last line without a newline";
        const std::string path = dir_.filePath("lines.txt").toStdString();
        writeText(path, text);
        std::vector<std::string> expected;
        std::istringstream in(text);
        for (std::string line; std::getline(in, line);)
            expected.push_back(line);
        for (std::size_t chunk : {1, 2, 7, 64, 121, 4096})
            for (bool suspend : {false, true})
                QCOMPARE(linesOf(path, chunk, suspend), expected);
        LineReader whole(path, 1000);
        std::string line;
        while (whole.next(line))
            QCOMPARE(whole.lastLineEnded(), line != "last line without a newline");
        QCOMPARE(whole.lineNumber(), long(expected.size()));
    }
    void lineEndCountsTheBytesOfWholeLines() {
        const std::string path = dir_.filePath("ends.txt").toStdString();
        writeText(path, "ab\ncde\nf");
        LineReader in(path, 10, 2);
        std::string line;
        QVERIFY(in.next(line) && in.lineEnd() == 3);
        QVERIFY(in.next(line) && in.lineEnd() == 7);
        QVERIFY(in.next(line) && line == "f" && !in.lastLineEnded());
        QVERIFY(!in.next(line));
    }
    void aLongLineIsRefusedAtTheLimit() {
        const std::string path = dir_.filePath("long.txt").toStdString();
        writeText(path, "short\n" + std::string(5000, 'x') + "\n");
        LineReader in(path, 1000, 64);
        std::string line;
        QVERIFY(in.next(line));
        try {
            in.next(line);
            QFAIL("a line over the limit was read");
        } catch (const LineReadError& e) {
            QVERIFY2(std::string(e.what()) == "line 2 is longer than the limit of 1000 bytes",
                     e.what());
        }
        LineReader zero("/dev/zero", 1000); // no line breaks at all: refused after 1000 bytes
        QVERIFY_THROWS_EXCEPTION(LineReadError, zero.next(line));
    }
    void aReadErrorIsNotTheEnd() {
        LineReader mem("/proc/self/mem", 1000); // address 0 is never mapped: read gives EIO
        std::string line;
        try {
            mem.next(line);
            QFAIL("a failed read was taken for the end of the file");
        } catch (const LineReadError& e) {
            QVERIFY2(std::string(e.what()).find("not the end of the file") != std::string::npos,
                     e.what());
        }
    }
    void aReplacedFileIsRefused() {
        const std::string path = dir_.filePath("replaced.txt").toStdString();
        writeText(path, "one\ntwo\n");
        LineReader in(path, 100, 4);
        std::string line;
        QVERIFY(in.next(line));
        in.suspend();
        const std::string other = dir_.filePath("other.txt").toStdString();
        writeText(other, "one\nTWO\n");
        QCOMPARE(std::rename(other.c_str(), path.c_str()), 0);
        QVERIFY_THROWS_EXCEPTION(LineReadError, in.next(line));
    }
    void pathsWithNulOrFoldersAreRefused() {
        QVERIFY_THROWS_EXCEPTION(LineReadError, LineReader(std::string("/dev/null\0x", 11), 100));
        QVERIFY_THROWS_EXCEPTION(LineReadError, LineReader(dir_.path().toStdString(), 100));
        QVERIFY_THROWS_EXCEPTION(LineReadError,
                                 LineReader(dir_.filePath("none").toStdString(), 100));
    }
};

QTEST_APPLESS_MAIN(TestLineReader)
#include "tst_line_reader.moc"
