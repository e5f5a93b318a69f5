// SPDX-License-Identifier: GPL-3.0-or-later
// Accelerogram readers (docs/theory.md §7): every shipped sample record parses with its header's
// point count, dt and the peak values listed in resources/records/SOURCES.md; header variants
// listed in SOURCES.md "Parser notes" parse; every broken-file mode is a RecordError with a line
// number.

#include "core/records/At2Reader.h"
#include "core/records/CsmipV2Reader.h"
#include "core/records/RecordReader.h"

#include <QtTest>

#include <cmath>
#include <fstream>
#include <sstream>

using namespace kinstab;

namespace {

const std::string kRecords = KINSTAB_SOURCE_DIR "/resources/records/";

std::string fileText(const std::string& name) {
    std::ifstream in(kRecords + name, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

// The first n lines of a text (with their line ends).
std::string firstLines(const std::string& text, int n) {
    std::size_t at = 0;
    for (int i = 0; i < n && at != std::string::npos; ++i)
        at = text.find('\n', at + 1);
    return text.substr(0, at == std::string::npos ? text.size() : at + 1);
}

std::string replaceLine(const std::string& text, int lineNumber, const std::string& with) {
    std::size_t start = 0;
    for (int i = 1; i < lineNumber; ++i)
        start = text.find('\n', start) + 1;
    const std::size_t end = text.find('\n', start);
    return text.substr(0, start) + with + text.substr(end);
}

constexpr double kCmS2 = 0.01 / 9.80665; // g per cm/s²

} // namespace

class TestRecordReaders : public QObject {
    Q_OBJECT
private slots:
    void sampleRecords_data();
    void sampleRecords();
    void headerPeaksAgreeWithData_data();
    void headerPeaksAgreeWithData();
    void at2HeaderVariants_data();
    void at2HeaderVariants();
    void csmipChannelsAreListed();
    void twoColumnText();
    void unitsConvert_data();
    void unitsConvert();
    void brokenFiles_data();
    void brokenFiles();
    void missingFile();
};

void TestRecordReaders::sampleRecords_data() {
    QTest::addColumn<QString>("file");
    QTest::addColumn<QString>("channel");
    QTest::addColumn<double>("dtGiven"); // 0: the header gives dt
    QTest::addColumn<int>("npts");
    QTest::addColumn<double>("dt");
    QTest::addColumn<double>("peak"); // signed, g (NaN: compare |peak|, sign unknown)
    QTest::addColumn<double>("absPeak");
    QTest::addColumn<double>("tol"); // half a unit of the last digit SOURCES.md prints
    QTest::addColumn<QString>("format");
    const double nan = std::nan("");
    // Values: resources/records/SOURCES.md (peaks as published there).
    QTest::newRow("SOURCES§1 RSN77 PUL164 +1.219g")
        << "RSN77_SFERN_PUL164.AT2"
        << "" << 0.0 << 4172 << 0.01 << 1.219 << 1.219 << 5e-4 << "PEER AT2";
    QTest::newRow("SOURCES§2 Rinaldi228 -0.874g")
        << "Rinaldi228.AT2"
        << "" << 0.0 << 1991 << 0.01 << -0.874 << 0.874 << 5e-4 << "PEER AT2";
    QTest::newRow("SOURCES§2 Rinaldi318 +0.472g")
        << "Rinaldi318.AT2"
        << "" << 0.0 << 1991 << 0.01 << 0.472 << 0.472 << 5e-4 << "PEER AT2";
    QTest::newRow("SOURCES§2 RinaldiUP +0.958g")
        << "RinaldiUP.AT2"
        << "" << 0.0 << 1991 << 0.01 << 0.958 << 0.958 << 5e-4 << "PEER AT2";
    QTest::newRow("SOURCES§3 RSN6 ElCentro180 -0.2808g")
        << "RSN6_IMPVALL.I_I-ELC180.AT2"
        << "" << 0.0 << 5372 << 0.01 << -0.2808 << 0.2808 << 5e-5 << "PEER AT2";
    QTest::newRow("SOURCES§3 BM68elc no header 0.0567g")
        << "BM68elc.acc"
        << "" << 0.01 << 4000 << 0.01 << nan << 0.0567 << 5e-5 << "values";
    QTest::newRow("SOURCES§4 RSN68 PEL090 0.2248g")
        << "RSN68_SFERN_PEL090.AT2"
        << "" << 0.0 << 7945 << 0.01 << 0.2248 << 0.2248 << 5e-5 << "PEER AT2";
    QTest::newRow("SOURCES§4 RSN68 PEL180 -0.1949g")
        << "RSN68_SFERN_PEL180.AT2"
        << "" << 0.0 << 7945 << 0.01 << -0.1949 << 0.1949 << 5e-5 << "PEER AT2";
    QTest::newRow("SOURCES§4 RSN68 PEL-UP 0.1643g")
        << "RSN68_SFERN_PEL-UP.AT2"
        << "" << 0.0 << 7945 << 0.01 << 0.1643 << 0.1643 << 5e-5 << "PEER AT2";
    QTest::newRow("SOURCES§4 RSN57 ORRDWN -0.1666g")
        << "RSN57_SFERN_ORRDWN.AT2"
        << "" << 0.0 << 6181 << 0.01 << -0.1666 << 0.1666 << 5e-5 << "PEER AT2";
    QTest::newRow("SOURCES§2 pacoima_dam.V2 RAD 429.355cm/s2")
        << "pacoima_dam.V2"
        << "RAD" << 0.0 << 551 << 0.02 << 429.355 * kCmS2 << 429.355 * kCmS2 << 5e-4 * kCmS2
        << "CSMIP V2";
    QTest::newRow("SOURCES§2 pacoima_dam.V2 UP -398.75cm/s2")
        << "pacoima_dam.V2"
        << "10" << 0.0 << 551 << 0.02 << -398.75 * kCmS2 << 398.75 * kCmS2 << 5e-3 * kCmS2
        << "CSMIP V2";
    QTest::newRow("SOURCES§2 pacoima_dam.V2 TAN 518.43cm/s2")
        << "pacoima_dam.V2"
        << "tan" << 0.0 << 551 << 0.02 << 518.43 * kCmS2 << 518.43 * kCmS2 << 5e-3 * kCmS2
        << "CSMIP V2";
    const std::string v1 = "16371-1605048211R_us1000hyfh_np8040r_NP8040-n.1000hyfh.HNE.";
    QTest::newRow("SOURCES§5 V1c basement -203.1cm/s2")
        << QString::fromStdString(v1 + "01.V1c") << "" << 0.0 << 42000 << 0.005 << -203.1 * kCmS2
        << 203.1 * kCmS2 << 0.05 * kCmS2 << "COSMOS V1";
    QTest::newRow("SOURCES§5 V1c 8th floor 364.4cm/s2")
        << QString::fromStdString(v1 + "17.V1c") << "" << 0.0 << 42000 << 0.005 << 364.4 * kCmS2
        << 364.4 * kCmS2 << 0.05 * kCmS2 << "COSMOS V1";
    QTest::newRow("SOURCES§5 V1c roof 436.4cm/s2")
        << QString::fromStdString(v1 + "32.V1c") << "" << 0.0 << 42000 << 0.005 << 436.4 * kCmS2
        << 436.4 * kCmS2 << 0.05 * kCmS2 << "COSMOS V1";
    // V2c: SOURCES.md §6 gives no peak; the file's text header line 11 says Max = -6.852 cm/sec2.
    QTest::newRow("SOURCES§6 V2c header line 11 -6.852cm/s2")
        << "us1000hyfh_akbmrp_AKBMR--n.1000hyfh.BNZ.--.acc.V2c"
        << "" << 0.0 << 42000 << 0.005 << -6.852 * kCmS2 << 6.852 * kCmS2 << 5e-4 * kCmS2
        << "COSMOS V2";
    // CE58667.V2: SOURCES.md §6 gives no peak; channel 1's header says 27.114 cm/sec/sec.
    QTest::newRow("SOURCES§6 CE58667 chan1 header 27.114cm/s2")
        << "CE58667.V2"
        << "1" << 0.0 << 7500 << 0.01 << 27.114 * kCmS2 << 27.114 * kCmS2 << 5e-4 * kCmS2
        << "CSMIP V2";
}

void TestRecordReaders::sampleRecords() {
    QFETCH(QString, file);
    QFETCH(QString, channel);
    QFETCH(double, dtGiven);
    QFETCH(int, npts);
    QFETCH(double, dt);
    QFETCH(double, peak);
    QFETCH(double, absPeak);
    QFETCH(double, tol);
    QFETCH(QString, format);
    RecordReadOptions o;
    o.channel = channel.toStdString();
    if (dtGiven > 0) o.dt = dtGiven;
    const Accelerogram a = readRecord(kRecords + file.toStdString(), o);
    QCOMPARE(static_cast<int>(a.size()), npts);
    QCOMPARE(a.dt, dt);
    QCOMPARE(QString::fromStdString(a.format), format);
    const SignedPeak p = a.peak();
    if (!std::isnan(peak)) QCOMPARE_LE(std::abs(p.value - peak), tol);
    QCOMPARE_LE(std::abs(std::abs(p.value) - absPeak), tol);
}

// Where a header states the peak, the data must agree with it to the header's printed digits.
void TestRecordReaders::headerPeaksAgreeWithData_data() {
    QTest::addColumn<QString>("file");
    QTest::addColumn<QString>("channel");
    QTest::addColumn<double>("tol"); // g: half a unit of the header's last digit
    QTest::newRow("pacoima_dam.V2 chan 9") << "pacoima_dam.V2"
                                           << "9" << 5e-4 * kCmS2;
    QTest::newRow("pacoima_dam.V2 chan 10") << "pacoima_dam.V2"
                                            << "10" << 5e-4 * kCmS2;
    QTest::newRow("pacoima_dam.V2 chan 11") << "pacoima_dam.V2"
                                            << "11" << 5e-4 * kCmS2;
    QTest::newRow("CE58667.V2 H1") << "CE58667.V2"
                                   << "H1" << 5e-4 * kCmS2;
    QTest::newRow("CE58667.V2 Up") << "CE58667.V2"
                                   << "Up" << 5e-4 * kCmS2;
    QTest::newRow("CE58667.V2 H2") << "CE58667.V2"
                                   << "H2" << 5e-4 * kCmS2;
    QTest::newRow("V2c real#64") << "us1000hyfh_akbmrp_AKBMR--n.1000hyfh.BNZ.--.acc.V2c"
                                 << "" << 5e-7 * kCmS2;
}

void TestRecordReaders::headerPeaksAgreeWithData() {
    QFETCH(QString, file);
    QFETCH(QString, channel);
    QFETCH(double, tol);
    RecordReadOptions o;
    o.channel = channel.toStdString();
    const Accelerogram a = readRecord(kRecords + file.toStdString(), o);
    QVERIFY(a.headerPeak.has_value());
    QVERIFY2(std::abs(std::abs(a.peak().value) - std::abs(*a.headerPeak)) <= tol,
             qPrintable(QString("data %1 header %2").arg(a.peak().value).arg(*a.headerPeak)));
}

// SOURCES.md "Parser notes": the header variants that the shipped files do not all show.
void TestRecordReaders::at2HeaderVariants_data() {
    QTest::addColumn<QString>("text");
    QTest::addColumn<double>("dt");
    QTest::addColumn<double>("last");
    QTest::newRow("older NGA: values first 'NPTS, DT'")
        << "PEER NGA STRONG MOTION DATABASE RECORD\nSAN FERNANDO 02/09/71 14:00, PACOIMA DAM, 164 "
           "(CDMG STATION 279)\n"
           "ACCELERATION TIME HISTORY IN UNITS OF G\n3    0.0100    NPTS, DT\n0.305422E-03 "
           "0.1E-02\n-0.25E-01\n"
        << 0.01 << -0.025;
    QTest::newRow("PEER 2000: 'NPTS=  4000, DT= .01000 SEC'")
        << "PEER STRONG MOTION DATABASE RECORD. PROCESSING BY PACIFIC ENGINEERING.\nIMPERIAL "
           "VALLEY 05/19/40 0439, EL CENTRO ARRAY #9, 180\n"
           "ACCELERATION TIME HISTORY IN UNITS OF G. FILTER POINTS: HP=0.2 Hz LP=15.0 Hz\nNPTS=  "
           "3, DT= .01000 SEC\n  .1E-02  -.2E-02   .3E-02\n"
        << 0.01 << 0.003;
    QTest::newRow("free text, 8F10.5, '(g)'")
        << "Data for El Centro 1940 North South Component (Peknold Version)\nformat of 8F10.5\nThe "
           "units are (g)\n"
           "NPTS=  3, DT= .02000 SEC\n   0.00630   0.00364   0.00099\n"
        << 0.02 << 0.00099;
    QTest::newRow("rotated, leading digit, CRLF")
        << "PEER NGA STRONG MOTION DATABASE RECORD - Rotated\r\nRSN1044, Clockwise rot. 0 deg\r\n"
           "ACCELERATION TIME SERIES IN UNITS OF G\r\nNPTS=  3, DT=   0.020 SEC\r\n-1.65951E-03 "
           "-1.6E-03 2.5E-03\r\n"
        << 0.02 << 0.0025;
    QTest::newRow("West2 with filter text after DT")
        << "PEER NGA STRONG MOTION DATABASE RECORD\nNorthridge-01, 1/17/1994, Rinaldi Receiving "
           "Sta, 228\n"
           "ACCELERATION TIME SERIES IN UNITS OF G\nNPTS=   3, DT=   .0100 SEC,   0 POLE @    "
           "30.00000 HZ,  -5 POLE @      .05000\n"
           "  -.2556093E-02  -.2534838E-02  -.2450926E-02\n"
        << 0.01 << -0.002450926;
}

void TestRecordReaders::at2HeaderVariants() {
    QFETCH(QString, text);
    QFETCH(double, dt);
    QFETCH(double, last);
    const Accelerogram a = parseRecord(RecordText(text.toStdString(), "variant.AT2"));
    QCOMPARE(a.format, std::string("PEER AT2"));
    QCOMPARE(static_cast<int>(a.size()), 3);
    QCOMPARE(a.dt, dt);
    QCOMPARE(a.samples.back(), last);
}

void TestRecordReaders::csmipChannelsAreListed() {
    const auto channels = csmipChannels(RecordText(fileText("pacoima_dam.V2"), "pacoima_dam.V2"));
    QCOMPARE(channels.size(), std::size_t(3));
    QCOMPARE(channels[1].number, 10);
    QCOMPARE(channels[1].name, std::string("UP"));
    const Accelerogram up =
        readRecord(kRecords + "pacoima_dam.V2", {RecordFormat::Auto, {}, {}, "UP"});
    QCOMPARE(up.station, std::string("PACOIMA RESERVOIR - PACOIMA DAM"));
    QCOMPARE(up.component, std::string("CHAN 10: UP"));
    const Accelerogram pul = readRecord(kRecords + "RSN77_SFERN_PUL164.AT2");
    QCOMPARE(pul.station, std::string("Pacoima Dam (upper left abut)"));
    QCOMPARE(pul.component, std::string("164"));
}

// Two columns with a header line, commas or tabs; time equally spaced to rounding.
void TestRecordReaders::twoColumnText() {
    const Accelerogram csv =
        parseRecord(RecordText("tiempo,amplitud\n0.00,0.1\n0.02,-0.2\n0.04,0.3\n", "a.csv"),
                    {RecordFormat::Auto, {}, AccelUnit::MetresPerS2, {}});
    QCOMPARE(csv.format, std::string("time-accel"));
    QCOMPARE(csv.size(), std::size_t(3));
    QCOMPARE_LT(std::abs(csv.dt - 0.02), 1e-15);
    QCOMPARE(csv.samples[2], 0.3 / 9.80665);
    const Accelerogram tab = parseRecord(RecordText("0\t-2.205\n0.02\t1.0\n", "b.dat"));
    QCOMPARE(tab.samples.front(), -2.205);
}

void TestRecordReaders::unitsConvert_data() {
    QTest::addColumn<QString>("unit");
    QTest::addColumn<double>("gPerUnit");
    // Standard gravity 9.80665 m/s²; 1 ft = 0.3048 m, 1 in = 0.0254 m (exact definitions).
    QTest::newRow("g") << "g" << 1.0;
    QTest::newRow("m/s2") << "m/s2" << 1.0 / 9.80665;
    QTest::newRow("cm/s2") << "cm/s2" << 1.0 / 980.665;
    QTest::newRow("gal") << "gal" << 1.0 / 980.665;
    QTest::newRow("ft/s2 = 32.174 ft/s2 per g") << "ft/s2" << 0.3048 / 9.80665;
    QTest::newRow("in/s2 = 386.09 in/s2 per g") << "in/s2" << 0.0254 / 9.80665;
}

void TestRecordReaders::unitsConvert() {
    QFETCH(QString, unit);
    QFETCH(double, gPerUnit);
    const auto u = accelUnitFromName(unit.toStdString());
    QVERIFY(u.has_value());
    RecordReadOptions o;
    o.dt = 0.01;
    o.unit = *u;
    const Accelerogram a = parseRecord(RecordText("1.0 2.0\n", "v.txt"), o);
    QCOMPARE_LE(std::abs(a.samples[1] - 2.0 * gPerUnit), 1e-15);
    QVERIFY(!accelUnitFromName("furlong/s2").has_value());
}

void TestRecordReaders::brokenFiles_data() {
    QTest::addColumn<QString>("text");
    QTest::addColumn<int>("format"); // RecordFormat
    QTest::addColumn<double>("dt");  // 0: not given
    QTest::addColumn<QString>("channel");
    QTest::addColumn<int>("line");
    QTest::addColumn<QString>("message");
    const std::string head = "PEER NGA STRONG MOTION DATABASE RECORD\nX, 1/1/2000, Y, "
                             "90\nACCELERATION TIME SERIES IN UNITS OF G\n";
    const int at2 = int(RecordFormat::At2), autoF = int(RecordFormat::Auto);
    auto row = [](const char* name, const std::string& text, int format, double dt,
                  const QString& ch, int line, const QString& msg) {
        QTest::newRow(name) << QString::fromStdString(text) << format << dt << ch << line << msg;
    };
    row("empty file", "", autoF, 0, "", 0, "empty file");
    row("blank lines only", "\n  \n\n", autoF, 0, "", 0, "empty file");
    row("AT2 truncated in the header", head, at2, 0, "", 3, "no 'NPTS=..., DT=...' line");
    row("AT2 truncated data", head + "NPTS= 5, DT= .01 SEC\n .1E-02 .2E-02\n .3E-02\n", autoF, 0,
        "", 6, "announces 5 values, the file has 3");
    row("AT2 more values than NPTS", head + "NPTS= 2, DT= .01 SEC\n .1E-02 .2E-02 .3E-02\n", autoF,
        0, "", 4, "announces 2 values, the file has 3");
    row("AT2 NaN value", head + "NPTS= 3, DT= .01 SEC\n .1E-02 .2E-02\n nan\n", autoF, 0, "", 6,
        "'nan' is not a finite number");
    row("AT2 garbage value", head + "NPTS= 3, DT= .01 SEC\n .1E-02 1.2.3 .2E-02\n", autoF, 0, "", 5,
        "value 2 '1.2.3' is not a number");
    row("AT2 NPTS not a number", head + "NPTS= abc, DT= .01 SEC\n .1E-02\n", autoF, 0, "", 4,
        "NPTS 'abc' is not a number");
    row("AT2 NPTS negative", head + "NPTS= -5, DT= .01 SEC\n .1E-02\n", autoF, 0, "", 4,
        "NPTS '-5' must be a whole number");
    row("AT2 NPTS fractional", head + "NPTS= 2.5, DT= .01 SEC\n .1E-02\n", autoF, 0, "", 4,
        "NPTS '2.5' must be a whole number");
    row("AT2 DT zero", head + "NPTS= 2, DT= 0.0 SEC\n .1E-02 .2E-02\n", autoF, 0, "", 4,
        "DT '0.0' must be > 0");
    row("AT2 DT missing", head + "NPTS= 2, DT= SEC\n .1E-02 .2E-02\n", autoF, 0, "", 4,
        "DT 'SEC' is not a number");
    row("AT2 unknown units",
        "PEER\nX, 1/1/2000, Y, 90\nACCELERATION IN UNITS OF FURLONGS\nNPTS= 2, DT= .01\n1 2\n",
        autoF, 0, "", 3, "unknown units");
    const std::string v2 = fileText("pacoima_dam.V2");
    row("CSMIP V2 accel block truncated", firstLines(v2, 60), autoF, 0, "", 60,
        "data end after 112 of 551 values");
    row("CSMIP V2 unknown channel", v2, autoF, 0, "VERT", 0,
        "channel 'VERT' is not in the file; it has: 9 RAD, 10 UP, 11 TAN");
    row("CSMIP V2 bad value", replaceLine(v2, 47, "      .699     1.8x3     1.644"), autoF, 0, "",
        47, "value 2 '1.8x3' is not a number");
    row("CSMIP V2 veloc block reached early",
        replaceLine(v2, 115,
                    "  551 POINTS OF VELOC DATA EQUALLY SPACED AT  .020 SEC.  (UNITS: CM/SEC)"),
        autoF, 0, "", 115, "data end after 544 of 551");
    const std::string cosmos = fileText("us1000hyfh_akbmrp_AKBMR--n.1000hyfh.BNZ.--.acc.V2c");
    row("COSMOS truncated data", firstLines(cosmos, 100), autoF, 0, "", 100,
        "data end after 47 of 42000 values");
    row("COSMOS dt unknown (real #62 = -999)",
        replaceLine(cosmos, 38,
                    "    -999.000000    -999.000000     210.000000      -6.851512      76.215000"),
        autoF, 0, "", 53, "real header value 62");
    row("COSMOS NaN value", replaceLine(cosmos, 60, "            NaN"), autoF, 0, "", 60,
        "'NaN' is not a finite number");
    row("COSMOS header cut before the real block", firstLines(cosmos, 20), autoF, 0, "", 20,
        "file ends before the real header block");
    row("values: non-number", "0.1 0.2\n0.3 x\n", autoF, 0.01, "", 2,
        "value 4 'x' is not a number");
    row("values: one value only", "0.1\n", autoF, 0.01, "", 1, "found 1 values");
    row("single column without dt", "0.1\n0.2\n", autoF, 0, "", 1, "single-column record needs dt");
    row("time-accel: uneven time", "0 1\n0.01 2\n0.03 3\n", autoF, 0, "", 3,
        "samples must be equally spaced");
    row("time-accel: time goes back", "0 1\n0.01 2\n0.0 3\n", autoF, 0, "", 3, "does not increase");
    row("time-accel: three columns", "0 1 2\n0.01 2 3\n", autoF, 0, "", 1, "expected 2 columns");
    row("time-accel: infinite accel", "0 1\n0.01 inf\n", autoF, 0, "", 2,
        "acceleration 'inf' is not a finite number");
}

void TestRecordReaders::brokenFiles() {
    QFETCH(QString, text);
    QFETCH(int, format);
    QFETCH(double, dt);
    QFETCH(QString, channel);
    QFETCH(int, line);
    QFETCH(QString, message);
    RecordReadOptions o;
    o.format = static_cast<RecordFormat>(format);
    if (dt > 0) o.dt = dt;
    o.channel = channel.toStdString();
    try {
        parseRecord(RecordText(text.toStdString(), "broken.txt"), o);
        QFAIL("no error");
    } catch (const RecordError& e) {
        QVERIFY2(QString::fromStdString(e.message()).contains(message), e.what());
        QCOMPARE(e.line(), line);
        QVERIFY(QString(e.what()).startsWith("broken.txt:" + QString::number(line) + ": "));
    }
}

void TestRecordReaders::missingFile() {
    try {
        readRecord(kRecords + "no-such-file.AT2");
        QFAIL("no error");
    } catch (const RecordError& e) {
        QCOMPARE(e.line(), 0);
        QVERIFY(QString::fromStdString(e.message()).contains("cannot open"));
    }
}

QTEST_APPLESS_MAIN(TestRecordReaders)
#include "tst_records_readers.moc"
