// SPDX-License-Identifier: GPL-3.0-or-later
// Hostile and foreign input files: every limit of core/base/InputLimits.h is enforced with a
// message naming the input and the limit; a UTF-8 byte-order mark and Latin-1 header text are
// read; numbers parse the same in a German locale (decimal comma) as in C; header counts are
// checked before anything is reserved. Expected values are the Unicode code points of the
// characters involved, counts of the inputs built here, or the limits themselves.

#include "core/base/InputLimits.h"
#include "core/base/TextInput.h"
#include "core/friction/TripletCsv.h"
#include "core/io/JsonReader.h"
#include "core/io/MotionJson.h"
#include "core/io/Project.h"
#include "core/records/RecordReader.h"
#include "core/slab/History.h"
#include "core/sweep/Grid.h"

#include <QtTest>

#include <clocale>
#include <fstream>
#include <sstream>

using namespace kinstab;

namespace {

const std::string kRoot = KINSTAB_SOURCE_DIR;

std::string fileText(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

std::string replaceLine(const std::string& text, int lineNumber, const std::string& with) {
    std::size_t start = 0;
    for (int i = 1; i < lineNumber; ++i)
        start = text.find('\n', start) + 1;
    return text.substr(0, start) + with + text.substr(text.find('\n', start));
}

const std::string kAt2Head = "PEER NGA STRONG MOTION DATABASE RECORD\nX, 1/1/2000, Y, 90\n"
                             "ACCELERATION TIME SERIES IN UNITS OF G\n";

// The record error's message for text, or "" when it reads.
QString recordError(const std::string& text, const RecordReadOptions& o = {}) {
    try {
        parseRecord(RecordText(text, "f.txt"), o);
        return {};
    } catch (const RecordError& e) {
        return QString::fromStdString(e.what());
    }
}

QString projectError(const std::string& text) {
    try {
        parseProject(text);
        return {};
    } catch (const ProjectError& e) {
        return QString::fromStdString(e.what());
    }
}

const std::string kCosmos =
    kRoot + "/resources/records/us1000hyfh_akbmrp_AKBMR--n.1000hyfh.BNZ.--.acc.V2c";
const std::string kCsmip = kRoot + "/resources/records/pacoima_dam.V2";
const std::string kExample = kRoot + "/resources/examples/paper-16-story.json";

// Runs f with the process's C locale set to German (decimal comma), as QApplication does
// from LANG=de_DE.UTF-8; skips when that locale is not installed (scripts/install-deps.sh).
template <class F> bool inGermanLocale(F f) {
    const std::string old = std::setlocale(LC_ALL, nullptr);
    if (!std::setlocale(LC_ALL, "de_DE.UTF-8")) return false;
    f();
    std::setlocale(LC_ALL, old.c_str());
    return true;
}

} // namespace

class TestInputLimits : public QObject {
    Q_OBJECT
private slots:
    void utf8AndLatin1();
    void elidedAndQuoted();
    void numbersIgnoreTheLocale();
    void boundedFileRead();
    void recordWithBomAndLatin1Header();
    void recordHeaderCounts();
    void recordNonsense();
    void fortranFormatOverflow();
    void jsonNesting();
    void projectLimits();
    void gridPoints();
    void historyRows();
    void frictionCsvWithBom();
    void recordOutsideProjectFolder();
};

void TestInputLimits::utf8AndLatin1() {
    QCOMPARE(withoutBom("\xEF\xBB\xBFname"), std::string_view("name"));
    QCOMPARE(withoutBom("name"), std::string_view("name"));
    QVERIFY(isValidUtf8("M\xC3\xA9xico"));     // é = U+00E9 = C3 A9
    QVERIFY(!isValidUtf8("M\xE9xico"));        // the same name in Latin-1
    QVERIFY(!isValidUtf8("\xC0\x80"));         // overlong NUL
    QVERIFY(!isValidUtf8("\xED\xA0\x80"));     // surrogate U+D800
    QVERIFY(!isValidUtf8("\xF4\x90\x80\x80")); // beyond U+10FFFF
    QCOMPARE(utf8FromLegacy("M\xE9xico"), std::string("M\xC3\xA9xico"));
    QCOMPARE(utf8FromLegacy("\xFF"), std::string("\xC3\xBF"));               // ÿ = U+00FF
    QCOMPARE(utf8FromLegacy("M\xC3\xA9xico"), std::string("M\xC3\xA9xico")); // unchanged
}

void TestInputLimits::elidedAndQuoted() {
    QCOMPARE(elided("abcdef", 3), std::string("abc..."));
    QCOMPARE(elided("abc", 3), std::string("abc"));
    QCOMPARE(elided("\xC3\xA9\xC3\xA9\xC3\xA9", 2), std::string("\xC3\xA9\xC3\xA9...")); // whole é
    const std::string q = quotedToken(std::string(10'000'000, 'x'));
    QCOMPARE(q.size(), limits::kMaxQuotedChars + 5); // quotes and "..."
}

void TestInputLimits::numbersIgnoreTheLocale() {
    const bool ran = inGermanLocale([] {
        QCOMPARE(parseDouble("1.5"), std::optional<double>(1.5));
        QCOMPARE(parseDouble("+2e-3"), std::optional<double>(0.002));
        QVERIFY(!parseDouble("1,5"));
        QCOMPARE(formatDouble(0.1), std::string("0.1"));
        // The shipped example's grid: 0.70 to 1.15 by 0.05 is 10 amplitudes.
        QCOMPARE(parseList("0.70:1.15:0.05").values.size(), std::size_t(10));
        QCOMPARE(parseList("1.5, 2.5").values, (std::vector<double>{1.5, 2.5}));
        const Project p = loadProject(kExample);
        QCOMPARE(p.grid.amplitudes.size(), std::size_t(10));
        QCOMPARE(p.grid.frequencies.size(), std::size_t(6)); // 0.5:1.125:0.125
        History h;
        h.samples.push_back({0.5, 0.25, 0.125, 1.5, 1});
        QCOMPARE(historyCsv(h), std::string("tau,accel_g,delta,velocity,state\n"
                                            "0.5,0.25,0.125,1.5,1\n"));
    });
    if (!ran) QSKIP("locale de_DE.UTF-8 is not installed (scripts/install-deps.sh makes it)");
    QCOMPARE(parseCount("99999999999999999999", SIZE_MAX), std::optional<std::size_t>());
    QCOMPARE(parseCount("42", 41), std::optional<std::size_t>());
    QCOMPARE(parseCount("42", 42), std::optional<std::size_t>(42));
}

void TestInputLimits::boundedFileRead() {
    const FileText zero = readTextFile("/dev/zero", 1 << 20); // never ends: stopped at the limit
    QVERIFY(zero.text.empty());
    QVERIFY(QString::fromStdString(zero.error).contains("larger than the limit of 1 MB"));
    QVERIFY(readTextFile(kRoot, 1 << 20).error.find("folder") != std::string::npos);
    QVERIFY(readTextFile(kRoot + "/no-such-file", 1 << 20).error.find("cannot open") == 0);
    QVERIFY(readTextFile(kExample, 1 << 20).error.empty());
    // A regular file over the limit is refused by its size, unread.
    QCOMPARE(readTextFile(kExample, 1000).error,
             std::string("larger than the limit of 1000 bytes for this kind of file"));
}

void TestInputLimits::recordWithBomAndLatin1Header() {
    const std::string at2 = "\xEF\xBB\xBF" + kAt2Head.substr(0, kAt2Head.find('\n') + 1) +
                            "M\xE9xico, 1/1/2000, Estaci\xF3n, 90\n"
                            "ACCELERATION TIME SERIES IN UNITS OF G\n"
                            "NPTS=  3, DT= .01 SEC\n .1E-02 -.2E-02 .3E-02\n";
    const Accelerogram a = parseRecord(RecordText(at2, "latin1.AT2"));
    QCOMPARE(a.format, std::string("PEER AT2"));
    QCOMPARE(a.size(), std::size_t(3));
    QCOMPARE(a.station, std::string("Estaci\xC3\xB3n")); // ó = U+00F3 = C3 B3
    QVERIFY(isValidUtf8(a.name));
    // A CSV of time and acceleration saved by Excel as "CSV UTF-8".
    const Accelerogram csv =
        parseRecord(RecordText("\xEF\xBB\xBFtime,accel\n0,0.1\n0.01,0.2\n", "x"));
    QCOMPARE(csv.size(), std::size_t(2));
    QCOMPARE(csv.dt, 0.01);
    // A 10 MB title line is cut for display.
    const std::string longName =
        kAt2Head.substr(0, kAt2Head.find('\n') + 1) + std::string(10'000'000, 'n') + "\n" +
        kAt2Head.substr(kAt2Head.rfind("ACC")) + "NPTS=  2, DT= .01 SEC\n .1E-02 .3E-02\n";
    QCOMPARE(parseRecord(RecordText(longName, "x")).name.size(), limits::kMaxNameChars + 3);
}

void TestInputLimits::recordHeaderCounts() {
    const std::string cosmos = fileText(kCosmos);
    QVERIFY(!cosmos.empty());
    // Line 53: "   42000 acceleration pts, approx  210 secs, units=cm/sec2(04),Format=(1E15.6)"
    QVERIFY(recordError(replaceLine(cosmos, 53,
                                    "   4000000000000000000 acceleration pts, "
                                    "approx 210 secs, units=cm/sec2(04),Format=(1E15.6)"))
                .contains("limit of 10000000"));
    QVERIFY(recordError(replaceLine(cosmos, 53,
                                    "   99999999999999999999999 acceleration pts, "
                                    "units=cm/sec2(04),Format=(1E15.6)"))
                .contains(":53: number of points '99999999999999999999999': expected a whole"));
    const QString noFormat = recordError(
        replaceLine(cosmos, 53, "   42000 acceleration pts, approx  210 secs, units=cm/sec2(04)"));
    QVERIFY2(noFormat.contains(":53: no Fortran data format"), qPrintable(noFormat));
    QVERIFY(recordError(replaceLine(cosmos, 14,
                                    " 99999999999999999999 Integer-header values "
                                    "follow on  10 lines, Format= (10I8)"))
                .contains(":14: header value count"));
    // CSMIP V2, line 46: "  551 POINTS OF ACCEL DATA EQUALLY SPACED AT  .020 SEC. ..."
    const std::string csmip = fileText(kCsmip);
    QVERIFY(!recordError(replaceLine(csmip, 46,
                                     "  1e300 POINTS OF ACCEL DATA EQUALLY SPACED AT  "
                                     ".020 SEC.  (UNITS: CM/SEC/SEC)"))
                 .isEmpty());
    QVERIFY(recordError(replaceLine(csmip, 46,
                                    "  99999999999999999999 POINTS OF ACCEL DATA "
                                    "EQUALLY SPACED AT  .020 SEC.  (UNITS: CM/SEC/SEC)"))
                .contains(":46: number of points"));
    QVERIFY(recordError(replaceLine(csmip, 1,
                                    "CORRECTED ACCELEROGRAM   24207-C0157-94019.02  "
                                    "     CHAN  99999999999: RAD         FROM   "))
                .contains(":1: channel number '99999999999'"));
    QVERIFY(recordError(kAt2Head + "NPTS= 4e18, DT= .01 SEC\n .1E-02 .2E-02\n")
                .contains("must be a whole number from 2 to 10000000"));
}

void TestInputLimits::recordNonsense() {
    QVERIFY(recordError(kAt2Head + "NPTS= 3, DT= .01 SEC\n .1E-02 1e308 .2E-02\n")
                .contains("sample 2 is 1e+308 g, beyond 100 g"));
    QVERIFY(recordError(kAt2Head + "NPTS= 3, DT= 1e300 SEC\n .1E-02 .1 .2E-02\n")
                .contains("sample interval 1e+300 s is outside"));
    RecordReadOptions channel;
    channel.channel = "abc";
    QVERIFY(recordError(kAt2Head + "NPTS= 2, DT= .01 SEC\n .1E-02 .2E-02\n", channel)
                .contains("channel 'abc' was asked for, but only CSMIP V2 files have channels"));
    // A CSMIP file takes the channel: UP is channel 10 of pacoima_dam.V2.
    channel.channel = "UP";
    QVERIFY(recordError(fileText(kCsmip), channel).isEmpty());
}

void TestInputLimits::fortranFormatOverflow() {
    QVERIFY(!parseFortranFormat("(99999999999999999999f10.3)"));
    QVERIFY(!parseFortranFormat("(8f99999999999999999999.3)"));
    QCOMPARE(parseFortranFormat("(8f10.3)")->perLine, 8);
    QCOMPARE(parseFortranFormat("(1E15.6)")->width, 15);
}

void TestInputLimits::jsonNesting() {
    const std::string deep = std::string(50'000, '[') + std::string(50'000, ']');
    QCOMPARE(jsonNestingDepth(deep, limits::kMaxJsonDepth), limits::kMaxJsonDepth + 1);
    const std::string strings =
        "{\"a\": \"[[[[\", \"b\": \"\\\"{{\"}"; // {"a": "[[[[", "b": "\"{{"}
    QCOMPARE(jsonNestingDepth(strings, 64), 1); // brackets in strings do not count
    QCOMPARE(jsonNestingDepth(std::string(64, '[') + std::string(64, ']'), 64), 64);
    QVERIFY(projectError(deep).contains("nested more than 64 levels deep"));
    // Within the limit, a wrong type deep inside is named without printing its whole value.
    const std::string example = fileText(kExample);
    std::string nested = example;
    nested.replace(nested.find("\"building\": {"), 13,
                   "\"building\": " + std::string(60, '[') + std::string(60, ']') + ", \"x\": {");
    QVERIFY2(projectError(nested).contains("building: expected an object, got an array of 1 "
                                           "entries"),
             qPrintable(projectError(nested)));
    std::string overflow = example;
    overflow.replace(overflow.find("\"format\""), 8, "\"x\": 1e999, \"format\"");
    QVERIFY(projectError(overflow).contains("number overflow"));
    QVERIFY(projectError("\xEF\xBB\xBF" + example).isEmpty()); // a BOM is not an error
}

void TestInputLimits::projectLimits() {
    const std::string example = fileText(kExample);
    std::string named = example;
    const std::size_t at = named.find("\"name\": \"") + 9;
    named.insert(at, std::string(10'000'000, 'N'));
    const QString e = projectError(named);
    QVERIFY2(e.contains("name: 10000033 characters, more than the limit of 200"), qPrintable(e));
    // A project file larger than 16 MB is refused before it is parsed.
    const std::string big = example + std::string(limits::kMaxProjectFileBytes, ' ');
    QVERIFY(projectError(big).contains("more than the limit of 16777216"));
}

void TestInputLimits::gridPoints() {
    const std::vector<double> a1000(1000, 1.0), a1001(1001, 1.0);
    QVERIFY(validateGrid({a1000, a1000}).empty()); // exactly the limit: 1000 x 1000
    const QString e = QString::fromStdString(validateGrid({a1001, a1000}));
    QVERIFY2(e.contains("1001 amplitudes x 1000 frequencies, more than the limit of 1000000"),
             qPrintable(e));
    QVERIFY(parseList("0:2:0.000001").error.find("limit of 1000000 values") != std::string::npos);
}

void TestInputLimits::historyRows() {
    QVERIFY(validateHistoryStep(20.0, 0.05).empty());
    // 20 / 1e-7 + 1 rows, the run of simulate --amplitude 1.2 --frequency 1 at that step.
    const QString e = QString::fromStdString(validateHistoryStep(20.0, 1e-7));
    QVERIFY2(e.contains("200000001 rows, more than the limit of 2000000"), qPrintable(e));
    QVERIFY(!validateHistoryStep(20.0, 0.0).empty());
}

void TestInputLimits::frictionCsvWithBom() {
    const std::string csv = "\xEF\xBB\xBF"
                            "configuration,cp_psi,test_no,delta_in,shear_kips\n"
                            "A,100,1,0.00,30\nA,100,1,0.05,20\nA,100,1,0.10,18\n";
    const std::vector<TripletCurve> curves = parseTripletCsv(csv, "bom.csv");
    QCOMPARE(curves.size(), std::size_t(1));
    QCOMPARE(curves[0].delta.size(), Eigen::Index(3));
}

void TestInputLimits::recordOutsideProjectFolder() {
    QVERIFY(!leavesProjectFolder("records/X.AT2", "/p/proj"));
    QVERIFY(!leavesProjectFolder("/p/proj/records/X.AT2", "/p/proj"));
    QVERIFY(leavesProjectFolder("../X.AT2", "/p/proj"));
    QVERIFY(leavesProjectFolder("/data/X.AT2", "/p/proj"));
    QVERIFY(leavesProjectFolder("records/../../X.AT2", "/p/proj"));
    QVERIFY(!leavesProjectFolder("X.AT2", "")); // no project folder: nothing to leave
}

QTEST_GUILESS_MAIN(TestInputLimits)
#include "tst_input_limits.moc"
