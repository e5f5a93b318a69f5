// SPDX-License-Identifier: GPL-3.0-or-later
// The records compiled into the programs (core/records/ShippedRecords.h, issue 34: kinstab-cli
// reads the shipped RSN68 UP without Qt's resources): the text is the file's in resources/records/
// byte for byte, and the planar case's vertical record read through core/slab/VerticalRecord.h is
// the one a record file gives.

#include "core/base/InputError.h"
#include "core/records/RecordReader.h"
#include "core/records/ShippedRecords.h"
#include "core/slab/VerticalRecord.h"

#include <QtTest>

#include <fstream>
#include <sstream>

using namespace kinstab;

namespace {
const std::string kRsn68Up = KINSTAB_SOURCE_DIR "/resources/records/RSN68_SFERN_PEL-UP.AT2";

std::string fileBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}
} // namespace

class TestShippedRecords : public QObject {
    Q_OBJECT
private slots:
    void textIsTheFile();
    void unknownNameIsEmpty();
    void verticalRecordIsTheFile();
    void missingFileNamesTheField();
};

void TestShippedRecords::textIsTheFile() {
    const std::string file = fileBytes(kRsn68Up);
    QVERIFY(file.size() > 100000); // the file was read: 7945 samples of AT2 text
    QVERIFY(shippedRecordText(kRsn68UpFileName) == file);
}

void TestShippedRecords::unknownNameIsEmpty() {
    QVERIFY(shippedRecordText("RSN77_SFERN_PUL164.AT2").empty()); // shipped as a file, not inside
}

void TestShippedRecords::verticalRecordIsTheFile() {
    PlanarSettings s;
    s.vertical = VerticalSource::Rsn68Up;
    const std::optional<Accelerogram> shipped = loadVerticalRecord(s);
    s.vertical = VerticalSource::File;
    s.verticalPath = kRsn68Up;
    const std::optional<Accelerogram> file = loadVerticalRecord(s);
    QVERIFY(shipped && file);
    QCOMPARE(shipped->samples.size(), std::size_t{7945}); // NPTS in the file's header
    QCOMPARE(shipped->dt, file->dt);
    QVERIFY(shipped->samples == file->samples);
    QCOMPARE(shipped->sourceFile, std::string(kRsn68UpSource));
    s.vertical = VerticalSource::None;
    QVERIFY(!loadVerticalRecord(s));
}

void TestShippedRecords::missingFileNamesTheField() {
    PlanarSettings s;
    s.vertical = VerticalSource::File;
    s.verticalPath = "/nonexistent/UP.AT2";
    try {
        loadVerticalRecord(s);
        QFAIL("no error for a missing file");
    } catch (const InputError& e) {
        QCOMPARE(std::string(e.what()),
                 std::string("planar.vertical = '/nonexistent/UP.AT2': No such file or directory"));
    }
}

QTEST_GUILESS_MAIN(TestShippedRecords)
#include "tst_shipped_records.moc"
