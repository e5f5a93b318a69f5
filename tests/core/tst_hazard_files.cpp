// SPDX-License-Identifier: GPL-3.0-or-later
// Hazard curves from files (core/risk/HazardFile.h):
//  - one curve written by the test as OpenQuake CSV (PoE in 50 years = 1 - exp(-50 lambda)), as
//    USGS JSON and as the plain CSV reads back as the same rates (to 1e-14) and gives the same
//    lambda_C (to 1e-13), whatever the format, found by its text or named;
//  - OpenQuake: the site is picked by lon,lat or the first row; trailing PoE 0 end the curve;
//    the depth column is optional; USGS: the response of the fragility's measure is picked;
//  - the measures' spellings (PGA, SA(0.2), SA0P2, sa(0.2s/5%)) are one measure;
//  - every bad file is a HazardError naming the file and the line (or JSON path) and the value.

#include "core/risk/HazardFile.h"
#include "core/risk/RiskIntegral.h"

#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <fstream>
#include <string>
#include <vector>

using namespace kinstab;

namespace {

// A second-order hazard (resources/examples/hazard-second-order.csv's parameters) at 12 points.
std::vector<HazardPoint> points() {
    std::vector<HazardPoint> p;
    for (int i = 0; i < 12; ++i) {
        const double x = 0.01 * std::pow(1.8, i), s = std::log(x);
        p.push_back({x, 2e-4 * std::exp(-0.2 * s * s - 2.2 * s)});
    }
    return p;
}

std::string num(double x) { // 17 significant digits: the double back exactly
    char b[40];
    std::snprintf(b, sizeof b, "%.17g", x);
    return b;
}

struct Site {
    double lon, lat;
    std::vector<double> poe;
};

// PoE in `years` of each point: 1 - exp(-years lambda).
std::vector<double> poes(const std::vector<HazardPoint>& p, double years = 50) {
    std::vector<double> v;
    for (const auto& q : p)
        v.push_back(-std::expm1(-years * q.annualRate));
    return v;
}

// The layout OpenQuake 3.x writes (core/risk/OpenQuakeHazard.cpp), depth column optional.
std::string openQuakeText(const std::vector<HazardPoint>& p, const std::vector<Site>& sites,
                          const std::string& imt, bool depth = true) {
    std::string t = "#,,,,\"generated_by='OpenQuake engine 3.16.0', start_date='2024-01-01', "
                    "kind='mean', investigation_time=50.0, imt='" +
                    imt + "'\"\nlon,lat" + (depth ? ",depth" : "");
    for (const auto& q : p)
        t += ",poe-" + num(q.imG);
    for (const Site& site : sites) {
        t += "\n" + num(site.lon) + "," + num(site.lat) + (depth ? ",0.0" : "");
        for (double x : site.poe)
            t += "," + num(x);
    }
    return t + "\n";
}

std::string openQuakeText(const std::vector<HazardPoint>& p, const std::string& imt) {
    return openQuakeText(p, {{-122.5, 37.75, poes(p)}}, imt);
}

std::string usgsText(const std::vector<HazardPoint>& p, const std::string& imt) {
    std::string x, y;
    for (const auto& q : p) {
        x += (x.empty() ? "" : ",") + num(q.imG);
        y += (y.empty() ? "" : ",") + num(q.annualRate);
    }
    const std::string pgv = "{\"metadata\": {\"imt\": {\"value\": \"PGV\"}, \"xvalues\": [1, 2]},"
                            " \"data\": [{\"yvalues\": [0.1, 0.01]}]}";
    return "{\"status\": \"success\", \"response\": [" + pgv +
           ", {\"metadata\": {\"imt\": {\"value\": \"" + imt +
           "\", \"display\": \"x\"}, \"xlabel\": \"Ground Motion (g)\", \"xvalues\": [" + x +
           "]}, \"data\": [{\"component\": \"Total\", \"yvalues\": [" + y +
           "]}, {\"component\": \"Grid\", \"yvalues\": [" + y + "]}]}]}";
}

std::string csvText(const std::vector<HazardPoint>& p, const std::string& comment = "") {
    std::string t = comment + "im_g,annual_rate\n";
    for (const auto& q : p)
        t += num(q.imG) + "," + num(q.annualRate) + "\n";
    return t;
}

HazardRequest measure(HazardMeasure m) {
    HazardRequest r;
    r.measure = m;
    return r;
}

const HazardMeasure kPga{HazardMeasure::Kind::Pga, 0};
const HazardMeasure kSa1{HazardMeasure::Kind::Sa, 1.0};

// The message of the HazardError parsing text throws, or "" when it throws none.
std::string errorOf(const std::string& text, const HazardRequest& r = {}) {
    try {
        parseHazardText(text, "h.txt", r);
    } catch (const HazardError& e) {
        return e.what();
    }
    return "";
}

} // namespace

class TestHazardFiles : public QObject {
    Q_OBJECT
private slots:
    void threeFormatsOneCurve() {
        const std::vector<HazardPoint> p = points();
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const std::string base = dir.path().toStdString() + "/";
        const std::vector<std::pair<std::string, std::string>> files = {
            {"hazard_curve-mean-PGA_1.csv", openQuakeText(p, "PGA")},
            {"usgs.json", usgsText(p, "PGA")},
            {"plain.csv", csvText(p, "# imt=PGA\n")}};
        const CollapseFragility f{0.5, 0.5};
        const double want =
            riskIntegral(hazardCurve(kPga, p, "", [](std::size_t) { return ""; }), f).lambdaC;
        for (const auto& [name, text] : files) {
            std::ofstream(base + name) << text;
            for (const HazardFormat format : {HazardFormat::Auto, detectHazardFormat(text)}) {
                HazardRequest r = measure(kPga);
                r.format = format;
                const HazardCurve c = readHazardFile(base + name, r);
                QCOMPARE(c.points.size(), p.size());
                QCOMPARE(hazardMeasureName(c.measure), std::string("PGA"));
                for (std::size_t i = 0; i < p.size(); ++i) {
                    QCOMPARE(c.points[i].imG, p[i].imG);
                    // OpenQuake's PoE in 50 years and back: -log1p(-PoE) / 50 (exact to rounding).
                    QCOMPARE_LE(std::abs(c.points[i].annualRate - p[i].annualRate),
                                1e-14 * p[i].annualRate);
                }
                QCOMPARE_LE(std::abs(riskIntegral(c, f).lambdaC - want), 1e-13 * want);
            }
        }
        QCOMPARE(detectHazardFormat(files[0].second), HazardFormat::OpenQuake);
        QCOMPARE(detectHazardFormat(files[1].second), HazardFormat::Usgs);
        QCOMPARE(detectHazardFormat(files[2].second), HazardFormat::Csv);
    }

    void openQuakeSitesAndZeros() {
        const std::vector<HazardPoint> p = points();
        // A site of PoE 0.5 everywhere first, then the curve's site.
        const std::string text = openQuakeText(
            p, {{10.0, 45.0, std::vector<double>(p.size(), 0.5)}, {-122.5, 37.75, poes(p)}},
            "SA(1.0)");
        HazardRequest r = measure(kSa1);
        QCOMPARE(parseHazardText(text, "oq.csv", r).points.front().annualRate,
                 -std::log1p(-0.5) / 50); // the first row, rates -ln(1 - PoE) / T
        r.site = HazardSite{-122.5, 37.75};
        const HazardCurve c = parseHazardText(text, "oq.csv", r);
        QCOMPARE_LE(std::abs(c.points[3].annualRate - p[3].annualRate), 1e-14 * p[3].annualRate);
        QVERIFY2(c.source.find("site -122.5,37.75 (line 4)") != std::string::npos,
                 c.source.c_str());
        r.site = HazardSite{0, 0};
        const std::string e = errorOf(text, r);
        QVERIFY2(e.find("no site within 0.0001 degrees of 0,0 among its 2 sites; the nearest is "
                        "10,45") != std::string::npos,
                 e.c_str());
        // The last two PoE written as 0 (beyond the simulated motions): the curve ends before.
        std::vector<double> zeros = poes(p);
        zeros[p.size() - 1] = zeros[p.size() - 2] = 0.0;
        const HazardCurve z = parseHazardText(openQuakeText(p, {{1, 2, zeros}}, "PGA"), "oq", {});
        QCOMPARE(z.points.size(), p.size() - 2);
        QCOMPARE(z.zeroRatePointsDropped, std::size_t(2));
        // A zero before a positive rate is a rate that increases.
        std::swap(zeros[p.size() - 3], zeros[p.size() - 1]);
        QVERIFY(errorOf(openQuakeText(p, {{1, 2, zeros}}, "PGA")).find("h.txt:3, column") == 0);
        // No depth column (older engines).
        const std::string noDepth = openQuakeText(p, {{1, 2, poes(p)}}, "PGA", false);
        QCOMPARE(parseHazardText(noDepth, "oq.csv", {}).points.size(), p.size());
        // A site asked of a file that holds one.
        r.site = HazardSite{1, 2};
        QVERIFY(errorOf(csvText(p), r).find("h.txt: a site is given, but a csv hazard file") == 0);
    }

    void usgsPicksTheMeasure() {
        const std::string text = usgsText(points(), "SA1P0");
        QCOMPARE(hazardMeasureName(parseHazardText(text, "u.json", measure(kSa1)).measure),
                 std::string("SA(1 s)"));
        // Two responses (PGV and SA1P0) and no measure asked for: name the one to use.
        QVERIFY(errorOf(text).find("2 intensity measures ('PGV' (unknown), 'SA1P0')") !=
                std::string::npos);
        const std::string e = errorOf(text, measure(kPga));
        QVERIFY2(e.find("no curve for the fragility's intensity measure PGA (it holds 'PGV' "
                        "(unknown), 'SA1P0')") != std::string::npos,
                 e.c_str());
    }

    void measureSpellings() {
        QVERIFY(sameMeasure(*measureFromOpenQuake("SA(0.2)"), *measureFromUsgs("SA0P2")));
        QVERIFY(sameMeasure(*measureFromUsgs("SA0P2"), *measureFromStudy("sa(0.2s/5%)")));
        QVERIFY(sameMeasure(*measureFromUsgs("SA10P0"), *measureFromOpenQuake("SA(10.0)")));
        QVERIFY(sameMeasure(*measureFromStudy("pga"), *measureFromOpenQuake("PGA")));
        QVERIFY(!sameMeasure(*measureFromStudy("pga"), *measureFromOpenQuake("SA(0.2)")));
        QVERIFY(!sameMeasure(*measureFromOpenQuake("SA(0.3)"), *measureFromOpenQuake("SA(0.2)")));
        QVERIFY(!measureFromStudy("sa(1s/2%)")); // no hazard source tabulates 2 % damping
        for (const char* bad : {"PGV", "SA()", "SA(-1)", "SA(nan)", "MMI", "SA(0.2"})
            QVERIFY2(!measureFromOpenQuake(bad), bad);
        for (const char* bad : {"PGV", "SAP2", "SA0P", "SA0X2", "SA-1P0"})
            QVERIFY2(!measureFromUsgs(bad), bad);
    }

    void badFilesNameTheFileAndLine_data() {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("message");
        const std::string pga = "# imt=PGA\nim_g,annual_rate\n";
        QTest::newRow("empty") << ""
                               << "h.txt: the file is empty";
        QTest::newRow("only a BOM and blanks") << "\xEF\xBB\xBF \n\n"
                                               << "h.txt: the file is empty";
        QTest::newRow("no data rows")
            << QString::fromStdString(pga) << "h.txt: 0 point(s) with a positive rate";
        QTest::newRow("one point") << QString::fromStdString(pga + "0.1,0.01\n")
                                   << "h.txt: 1 point(s) with a positive rate";
        QTest::newRow("rate increases")
            << QString::fromStdString(pga + "0.1,0.01\n0.2,0.001\n0.3,0.002\n")
            << "h.txt:5: annual rate 0.002 increases on the previous point's 0.001";
        QTest::newRow("intensity does not increase")
            << QString::fromStdString(pga + "0.1,0.01\n0.1,0.001\n")
            << "h.txt:4: intensity 0.1 g does not increase";
        QTest::newRow("NaN rate") << QString::fromStdString(pga + "0.1,0.01\n0.2,nan\n")
                                  << "h.txt:4: annual rate nan must be a finite number > 0";
        QTest::newRow("negative rate") << QString::fromStdString(pga + "0.1,0.01\n0.2,-1e-3\n")
                                       << "h.txt:4: annual rate -0.001 must be a finite number > 0";
        QTest::newRow("intensity in other units")
            << QString::fromStdString(pga + "0.1,0.01\n9810,0.001\n")
            << "h.txt:4: intensity 9810 g is outside 1e-06 to 1000 g: not an intensity in g";
        QTest::newRow("zero intensity") << QString::fromStdString(pga + "0,0.01\n0.2,1e-3\n")
                                        << "h.txt:3: intensity 0 g must be a finite number > 0";
        QTest::newRow("decimal comma")
            << QString::fromStdString(pga + "0,1;0,01\n") << "h.txt:3: 3 fields, expected 2";
        QTest::newRow("text") << QString::fromStdString(pga + "0.1,abc\n")
                              << "h.txt:3, column 'annual_rate': 'abc' is not a number";
        QTest::newRow("CSV header") << "im,rate\n0.1,0.01\n"
                                    << "h.txt:1: the header must be im_g,annual_rate";
        QTest::newRow("CSV unknown IMT") << "# imt=PGV\nim_g,annual_rate\n"
                                         << "h.txt:1: unknown intensity measure 'PGV'";
        const std::string oqHead = "#,\"kind='mean', investigation_time=50.0, imt='PGA'\"\n"
                                   "lon,lat,depth,poe-0.1,poe-0.2,poe-0.4\n";
        QTest::newRow("OpenQuake PoE 1") << QString::fromStdString(oqHead + "1,2,0,1.0,0.5,0.1\n")
                                         << "h.txt:3, column 'poe-0.1': PoE 1 is not below 1";
        QTest::newRow("OpenQuake PoE above 1")
            << QString::fromStdString(oqHead + "1,2,0,0.9,1.5,0.1\n")
            << "h.txt:3, column 'poe-0.2': PoE 1.5 is not below 1";
        QTest::newRow("OpenQuake negative PoE")
            << QString::fromStdString(oqHead + "1,2,0,0.9,-0.5,0.1\n")
            << "h.txt:3, column 'poe-0.2': PoE -0.5 must be a finite number >= 0";
        QTest::newRow("OpenQuake NaN PoE")
            << QString::fromStdString(oqHead + "1,2,0,0.9,nan,0.1\n")
            << "h.txt:3, column 'poe-0.2': PoE nan must be a finite number >= 0";
        QTest::newRow("OpenQuake PoE increases")
            << QString::fromStdString(oqHead + "1,2,0,0.5,0.6,0.1\n")
            << "h.txt:3, column 'poe-0.2': annual rate";
        QTest::newRow("OpenQuake short row") << QString::fromStdString(oqHead + "1,2,0,0.5\n")
                                             << "h.txt:3: 4 fields, the header has 6";
        QTest::newRow("OpenQuake unknown IMT")
            << "#,\"investigation_time=50.0, imt='PGV'\"\nlon,lat,poe-1\n"
            << "h.txt:1: unknown intensity measure imt='PGV'";
        QTest::newRow("OpenQuake no investigation time")
            << "#,\"investigation_time=, imt='PGA'\"\nlon,lat,poe-1\n"
            << "h.txt:1: investigation_time='' must be a number of years > 0";
        QTest::newRow("OpenQuake bad column")
            << "#,\"investigation_time=50, imt='PGA'\"\nlon,lat,poe-0.1,iml-0.2\n"
            << "h.txt:2: column 4 'iml-0.2' is not poe-X";
        QTest::newRow("OpenQuake IMT mismatch")
            << QString::fromStdString(oqHead + "1,2,0,0.5,0.1,0.01\n")
            << "h.txt:1: the hazard curve's intensity measure PGA is not the fragility's SA(1 s)";
        QTest::newRow("CSV IMT mismatch")
            << QString::fromStdString(pga + "0.1,0.01\n0.2,0.001\n")
            << "h.txt:1: the hazard curve's intensity measure PGA is not the fragility's SA(1 s)";
        QTest::newRow("USGS not JSON") << "{\"response\": ["
                                       << "h.txt: ";
        QTest::newRow("USGS unknown IMT")
            << "{\"response\": [{\"metadata\": {\"imt\": {\"value\": \"PGV\"}, \"xvalues\": [1, "
               "2]}, \"data\": [{\"yvalues\": [0.1, 0.01]}]}]}"
            << "h.txt: response[0].metadata.imt.value: unknown intensity measure 'PGV'";
        QTest::newRow("USGS lengths")
            << "{\"response\": [{\"metadata\": {\"imt\": {\"value\": \"PGA\"}, \"xvalues\": [1, "
               "2]}, \"data\": [{\"yvalues\": [0.1]}]}]}"
            << "h.txt: response[0].data[0].yvalues: 1 values for the 2 of "
               "response[0].metadata.xvalues";
        QTest::newRow("USGS text value")
            << "{\"response\": [{\"metadata\": {\"imt\": {\"value\": \"PGA\"}, \"xvalues\": [1, "
               "\"2\"]}, \"data\": [{\"yvalues\": [0.1, 0.01]}]}]}"
            << "h.txt: response[0].metadata.xvalues[1]: \"2\" is not a number";
        QTest::newRow("USGS rate increases")
            << "{\"response\": [{\"metadata\": {\"imt\": {\"value\": \"PGA\"}, \"xvalues\": [1, "
               "2]}, \"data\": [{\"yvalues\": [0.01, 0.1]}]}]}"
            << "h.txt: response[0].metadata.xvalues[1], response[0].data[0].yvalues[1]: annual "
               "rate 0.1 increases";
        QTest::newRow("USGS no response") << "{\"status\": \"error\"}"
                                          << "h.txt: (top level): missing (expected \"response\")";
    }
    void badFilesNameTheFileAndLine() {
        QFETCH(QString, text);
        QFETCH(QString, message);
        const bool mismatch = QString(QTest::currentDataTag()).contains("mismatch");
        const std::string e = errorOf(text.toStdString(), mismatch ? measure(kSa1) : measure(kPga));
        QVERIFY2(e.find(message.toStdString()) == 0, e.c_str());
    }

    void tooManyPoints() {
        std::string t = "im_g,annual_rate\n";
        for (std::size_t i = 0; i <= 10'000; ++i)
            t += std::to_string(i + 1) + ",1\n";
        QVERIFY(errorOf(t).find("h.txt:10002: more than the limit of 10000 points") == 0);
    }

    void missingFile() {
        try {
            readHazardFile("/nonexistent/hazard.csv", {});
            QFAIL("no error");
        } catch (const HazardError& e) {
            QVERIFY2(std::string(e.what()).find("/nonexistent/hazard.csv: ") == 0, e.what());
        }
    }
};

QTEST_GUILESS_MAIN(TestHazardFiles)
#include "tst_hazard_files.moc"
