// SPDX-License-Identifier: GPL-3.0-or-later
// Furgerson (1980) Table 2: the composite fits per configuration and CP, refitted from the
// Table 1 transcription. TRANSCRIPTION_NOTES.md (check 7) shows which rows the data reproduce:
// BJ-F-NG 100 and 200 fully, BJ-F-NG 300 (tests 6, 44, 13) except c. The other rows' composites
// differ from Table 2's own V1/Vbar columns by more than OCR errors explain, so for them we test
// the documented deviation: our fit equals the independent re-implementation's re-fit
// (cross_checks.txt, same alpha = 2, beta = 0, bound V_inf < min V) and differs from Table 2.

#include "FurgersonTables.h"

#include "core/friction/DecayFit.h"
#include "core/friction/FrictionCalibration.h"

#include <QtTest>

#include <cmath>

using namespace kinstab;

namespace {

struct Table2Row {
    double v1, vbar, b, c, vInf, bound, dV1;
    std::string beta;
};

Table2Row table2(const std::string& config, double cp) {
    for (const auto& r : furgerson::rows("table2_fits.csv"))
        if (r.at("configuration") == config && std::stod(r.at("cp_psi")) == cp)
            return {std::stod(r.at("V1")),
                    std::stod(r.at("Vbar")),
                    std::stod(r.at("b")),
                    std::stod(r.at("c")),
                    std::stod(r.at("V_inf")),
                    std::stod(r.at("vinf_bound")),
                    std::stod(r.at("V1_minus_Vdelta1")),
                    r.at("beta")};
    throw std::runtime_error("no Table 2 row");
}

TripletCurve composite(const std::string& config, double cp,
                       const std::vector<std::string>& tests = {}) {
    std::vector<TripletCurve> runs;
    for (const TripletCurve& c : runsOf(furgerson::table1(), config, cp))
        if (tests.empty() || std::find(tests.begin(), tests.end(), c.test) != tests.end())
            runs.push_back(c);
    return compositeCurve(runs);
}

std::vector<TripletCurve> runsOfTable1(const std::string& config, double cp) {
    return runsOf(furgerson::table1(), config, cp);
}

} // namespace

class TestFrictionTable2 : public QObject {
    Q_OBJECT
private slots:
    void reproducedRows_data();
    void reproducedRows();
    void bestBetaMatchesStars();
    void documentedDeviations_data();
    void documentedDeviations();
    void suggestedCorrectionBjfg300();
};

void TestFrictionTable2::reproducedRows_data() {
    QTest::addColumn<QString>("config");
    QTest::addColumn<double>("cp");
    QTest::addColumn<QStringList>("tests");
    QTest::addColumn<bool>("cReproduced");
    QTest::newRow("Table 2 BJ-F-NG 100") << "BJ-F-NG" << 100.0 << QStringList{} << true;
    QTest::newRow("Table 2 BJ-F-NG 200 (without #7)")
        << "BJ-F-NG" << 200.0 << QStringList{"30", "43", "34", "36", "21", "11"} << true;
    QTest::newRow("Table 2 BJ-F-NG 300 (tests 6,44,13)")
        << "BJ-F-NG" << 300.0 << QStringList{"6", "44", "13"} << false;
}

void TestFrictionTable2::reproducedRows() {
    // V1 and Vbar (composite at delta = 0 and 0.40) to the printed 0.1 kip (+-0.05); V_inf within
    // Table 2's own "+-" bound; b within 0.01 (printed to 2 decimals); c within 2 %. For
    // BJ-F-NG 300 c is a documented deviation: 11.40 against 10.26 (11 %), also in the re-fit
    // of cross_checks.txt.
    QFETCH(QString, config);
    QFETCH(double, cp);
    QFETCH(QStringList, tests);
    QFETCH(bool, cReproduced);
    std::vector<std::string> t;
    for (const QString& s : tests)
        t.push_back(s.toStdString());
    const TripletCurve comp = composite(config.toStdString(), cp, t);
    const Table2Row want = table2(config.toStdString(), cp);
    const DecayFit fit = fitDecayBestBeta(comp);
    qInfo("V1 %.2f (%.1f) Vbar %.2f (%.1f) V_inf %.3f (%.1f +-%.2f) c %.2f (%.2f) b %.3f (%.2f)",
          fit.v1, want.v1, comp.shear(8), want.vbar, fit.vInf, want.vInf, want.bound, fit.c, want.c,
          fit.b, want.b);
    QCOMPARE(fit.beta, 0.0);
    QCOMPARE_LE(std::abs(fit.v1 - want.v1), 0.05 + 1e-9); // 4.45 prints as 4.5
    QCOMPARE_LE(std::abs(comp.shear(8) - want.vbar), 0.05 + 1e-9);
    QCOMPARE_LE(std::abs(fit.vInf - want.vInf), want.bound);
    QCOMPARE_LE(std::abs(fit.b - want.b), 0.01);
    if (cReproduced)
        QCOMPARE_LE(std::abs(fit.c - want.c), 0.02 * want.c);
    else
        QCOMPARE_GT(std::abs(fit.c - want.c), 0.10 * want.c);
}

void TestFrictionTable2::bestBetaMatchesStars() {
    // Table 2 marks beta = 1/3 ("*") for BJ-F-G 400 and 500 only. Choosing the smaller f_m per
    // composite (all Table 1 runs of the group) reproduces that pattern on all 14 rows.
    for (const auto& r : furgerson::rows("table2_fits.csv")) {
        const std::string config = r.at("configuration");
        const double cp = std::stod(r.at("cp_psi"));
        std::vector<std::string> tests;
        if (config == "BJ-F-NG" && cp == 200) tests = {"30", "43", "34", "36", "21", "11"};
        if (config == "BJ-F-NG" && cp == 300) tests = {"6", "44", "13"};
        const DecayFit fit = fitDecayBestBeta(composite(config, cp, tests));
        QCOMPARE(fit.beta, r.at("beta") == "1/3" ? 1.0 / 3.0 : 0.0);
    }
}

void TestFrictionTable2::documentedDeviations_data() {
    QTest::addColumn<QString>("config");
    QTest::addColumn<double>("cp");
    QTest::addColumn<double>("vInf");
    QTest::addColumn<double>("c");
    QTest::addColumn<double>("b");
    // cross_checks.txt, "refit(beta=0)" of the composite of all Table 1 rows of the group.
    QTest::newRow("cross_checks BJ-F-G 100") << "BJ-F-G" << 100.0 << 15.15 << 11.11 << -0.009;
    QTest::newRow("cross_checks BJ-F-G 200") << "BJ-F-G" << 200.0 << 23.07 << 11.00 << 0.021;
    QTest::newRow("cross_checks BJ-F-G 300") << "BJ-F-G" << 300.0 << 22.41 << 3.09 << 0.002;
    QTest::newRow("cross_checks BJ-F-NG 400") << "BJ-F-NG" << 400.0 << 14.97 << 7.89 << 0.053;
    QTest::newRow("cross_checks BJ-F-NG 500") << "BJ-F-NG" << 500.0 << 7.58 << 1.98 << 0.040;
    QTest::newRow("cross_checks HJ-F-NG 100") << "HJ-F-NG" << 100.0 << 3.60 << 11.73 << 0.027;
    QTest::newRow("cross_checks HJ-F-NG 200") << "HJ-F-NG" << 200.0 << 8.43 << 13.24 << 0.026;
    QTest::newRow("cross_checks HJ-F-NG 300") << "HJ-F-NG" << 300.0 << 12.00 << 16.32 << 0.018;
    QTest::newRow("cross_checks HJ-F-NG 400") << "HJ-F-NG" << 400.0 << 15.30 << 8.34 << 0.065;
}

void TestFrictionTable2::documentedDeviations() {
    QFETCH(QString, config);
    QFETCH(double, cp);
    QFETCH(double, vInf);
    QFETCH(double, c);
    QFETCH(double, b);
    const DecayFit fit = fitDecay(composite(config.toStdString(), cp), 0.0);
    QCOMPARE_LE(std::abs(fit.vInf - vInf), 0.005 + 1e-9);
    QCOMPARE_LE(std::abs(fit.c - c), 0.005 + 1e-9);
    QCOMPARE_LE(std::abs(fit.b - b), 0.0005 + 1e-9);
    // ... and not Table 2: V_inf outside the printed bound, or c off by more than 5 %.
    const Table2Row want = table2(config.toStdString(), cp);
    QVERIFY(std::abs(fit.vInf - want.vInf) > want.bound ||
            std::abs(fit.c - want.c) > 0.05 * want.c);
}

void TestFrictionTable2::suggestedCorrectionBjfg300() {
    // suggested_corrections.csv: BJ-F-G-300 #39 at 0.40 printed 20.7 (implausible), probably
    // 29.4. With 29.4 the composite reproduces Table 2: Vbar 33.1, V_inf 28.5 +-0.42, c 4.36
    // (within 5 %), b -0.02, V1 - V(delta_1) -0.40.
    std::vector<TripletCurve> runs = runsOfTable1("BJ-F-G", 300);
    for (TripletCurve& r : runs)
        if (r.test == "39") r.shear(8) = 29.4;
    const TripletCurve comp = compositeCurve(runs);
    const Table2Row want = table2("BJ-F-G", 300);
    const DecayFit fit = fitDecayBestBeta(comp);
    QCOMPARE(fit.beta, 0.0);
    QCOMPARE_LE(std::abs(comp.shear(8) - want.vbar), 0.05 + 1e-9);
    QCOMPARE_LE(std::abs(fit.vInf - want.vInf), want.bound);
    QCOMPARE_LE(std::abs(fit.c - want.c), 0.05 * want.c);
    QCOMPARE_LE(std::abs(fit.b - want.b), 0.01);
    QCOMPARE_LE(std::abs((fit.v1 - fit.fitted(0)) - want.dV1), 0.01);
}

QTEST_APPLESS_MAIN(TestFrictionTable2)
#include "tst_friction_table2.moc"
