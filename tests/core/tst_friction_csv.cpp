// SPDX-License-Identifier: GPL-3.0-or-later
// Triplet test CSV import (layout of the transcribed Furgerson 1980 Table 1): the shipped
// table reads back as 46 curves, and every broken input is refused naming line and column.

#include "FurgersonTables.h"

#include "core/friction/TripletCsv.h"

#include <QtTest>

using namespace kinstab;

class TestFrictionCsv : public QObject {
    Q_OBJECT
private slots:
    void shippedTable1();
    void quotingAndColumnOrder();
    void badInput_data();
    void badInput();
    void missingFile();
};

void TestFrictionCsv::shippedTable1() {
    // TRANSCRIPTION_NOTES.md: 46 curves x 9 displacements = 414 rows.
    const std::vector<TripletCurve> curves = furgerson::table1();
    QCOMPARE(curves.size(), std::size_t(46));
    for (const TripletCurve& c : curves)
        QCOMPARE(c.delta.size(), Eigen::Index(9));
    // Table 3a run #7 (printed "2" in the Table 1 OCR, corrected by the transcriber):
    // 20.3 16.8 14.6 14.0 13.4 13.0 12.8 12.4 12.1.
    const TripletCurve run7 = furgerson::ng200Run("7");
    QCOMPARE(run7.shear(0), 20.3);
    QCOMPARE(run7.shear(8), 12.1);
    QCOMPARE(run7.delta(8), 0.40);
    // The "unknown" and "5(dup)" test labels are kept as strings.
    QVERIFY(std::any_of(curves.begin(), curves.end(),
                        [](const TripletCurve& c) { return c.test == "5(dup)"; }));
}

void TestFrictionCsv::quotingAndColumnOrder() {
    const std::string text = "# my lab, 2026\n"
                             "shear_kips,note,delta_in,test_no,cp_psi,configuration\n"
                             "12.0,\"peak, \"\"clean\"\"\",0,A1,150,BJ\n"
                             "9.0,,0.1,A1,150,BJ\n"
                             "\n"
                             "8.0,,0.2,A1,150,BJ\n";
    const std::vector<TripletCurve> c = parseTripletCsv(text, "lab.csv");
    QCOMPARE(c.size(), std::size_t(1));
    QCOMPARE(c[0].configuration, std::string("BJ"));
    QCOMPARE(c[0].cpPsi, 150.0);
    QCOMPARE(c[0].shear(2), 8.0);
    QCOMPARE(splitCsvLine("a,\"b,\"\"c\"\"\",d")[1], std::string("b,\"c\""));
}

void TestFrictionCsv::badInput_data() {
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("message");
    const QString h = "configuration,cp_psi,test_no,delta_in,shear_kips\n";
    QTest::newRow("not a number") << h + "BJ,100,1,0,12\nBJ,100,1,0.05,1O.5\nBJ,100,1,0.1,9\n"
                                  << "bad.csv line 3, column 'shear_kips': '1O.5' is not a number";
    QTest::newRow("missing column")
        << "configuration,cp_psi,test,delta_in,shear_kips\nBJ,100,1,0,12\n"
        << "bad.csv line 1: header has no column 'test_no'";
    QTest::newRow("short line") << h + "BJ,100,1,0\n"
                                << "bad.csv line 2, column 'shear_kips': missing";
    QTest::newRow("delta not increasing")
        << h + "BJ,100,1,0,12\nBJ,100,1,0.1,11\nBJ,100,1,0.1,10\n"
        << "bad.csv line 4, column 'delta_in': 0.1 does not increase";
    QTest::newRow("negative shear") << h + "BJ,100,1,0,-12\n"
                                    << "bad.csv line 2, column 'shear_kips': must be > 0";
    QTest::newRow("zero pressure") << h + "BJ,0,1,0,12\n"
                                   << "bad.csv line 2, column 'cp_psi': must be > 0";
    QTest::newRow("nan") << h + "BJ,100,1,nan,12\n"
                         << "bad.csv line 2, column 'delta_in': 'nan' is not a number";
    QTest::newRow("empty configuration") << h + ",100,1,0,12\n"
                                         << "bad.csv line 2, column 'configuration': empty";
    QTest::newRow("unterminated quote") << h + "\"BJ,100,1,0,12\n"
                                        << "bad.csv line 2: unterminated quoted field";
    QTest::newRow("empty file") << QString() << "bad.csv: empty file";
    QTest::newRow("header only") << h << "bad.csv: no data rows";
    QTest::newRow("too few samples") << h + "BJ,100,1,0,12\nBJ,100,1,0.1,11\n"
                                     << "needs at least 3 samples";
    QTest::newRow("no decay") << h + "BJ,100,1,0,12\nBJ,100,1,0.1,13\nBJ,100,1,0.2,14\n"
                              << "no post-peak decay";
}

void TestFrictionCsv::badInput() {
    QFETCH(QString, text);
    QFETCH(QString, message);
    try {
        parseTripletCsv(text.toStdString(), "bad.csv");
        QFAIL("accepted a broken file");
    } catch (const TripletCsvError& e) {
        if (!QString(e.what()).contains(message)) qWarning("message: %s", e.what());
        QVERIFY(QString(e.what()).contains(message));
    }
}

void TestFrictionCsv::missingFile() {
    QVERIFY_THROWS_EXCEPTION(TripletCsvError, readTripletCsv("/nonexistent/triplets.csv"));
}

QTEST_APPLESS_MAIN(TestFrictionCsv)
#include "tst_friction_csv.moc"
