// SPDX-License-Identifier: GPL-3.0-or-later
// kinstab-cli friction, run as a user would: JSON on the shipped Table 1, exit 2 with a message
// naming the flag or the CSV line and column for bad input.

#include <nlohmann/json.hpp>

#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>

namespace {

struct Run {
    int code;
    QByteArray out, err;
};

Run cli(const QStringList& args) {
    QProcess p;
    p.start(KINSTAB_CLI, QStringList{"friction"} + args);
    if (!p.waitForFinished(60000)) return {-1, {}, "timeout"};
    return {p.exitCode(), p.readAllStandardOutput(), p.readAllStandardError()};
}

const QString kTable1 =
    QString(KINSTAB_SOURCE_DIR) + "/resources/data/furgerson1980/table1_triplet_tests.csv";

} // namespace

class TestCliFriction : public QObject {
    Q_OBJECT
private slots:
    void table1Json();
    void badFlags_data();
    void badFlags();
    void badCsv();
};

void TestCliFriction::table1Json() {
    const Run r = cli({"--data", kTable1, "--bearing-area", "65.7"});
    QCOMPARE(r.code, 0);
    const nlohmann::json j = nlohmann::json::parse(r.out.toStdString());
    QCOMPARE(j["groups"].size(), std::size_t(14));
    for (const auto& g : j["groups"]) {
        if (g["configuration"] != "BJ-F-NG" || g["cp_psi"] != 200.0) continue;
        // Run #7 rejected at 95 % and left out (Furgerson 1980 ch. III); Table 3b (iv) fit.
        QVERIFY(g["outlier_test"]["rejected"].get<bool>());
        // Run #7's V_inf sits on its bound, min V = 12.1 (Table 3a prints 12.08).
        QCOMPARE_LE(std::abs(g["outlier_test"]["suspect_V_inf"].get<double>() - 12.1), 1e-5);
        QCOMPARE(g["composite_tests"].get<std::string>(), std::string("30,43,34,36,21,11"));
        QCOMPARE_LE(std::abs(g["fit"]["V_inf"].get<double>() - 8.87), 0.02);
        QCOMPARE(g["fit"]["alpha"].get<double>(), 2.0);
        QCOMPARE(g["fit"]["beta"].get<double>(), 0.0);
        QCOMPARE(g["intervals"].size(), std::size_t(3));
    }
    for (const auto& c : j["configurations"]) {
        QVERIFY(c["with_intercept"]["mu_inf"].is_number());
        QVERIFY(c["through_origin"]["mu_inf"].is_number());
        QCOMPARE(c["points_used"].get<int>(), 4);
    }
}

void TestCliFriction::badFlags_data() {
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QString>("message");
    QTest::newRow("unknown flag") << QStringList{"--data", kTable1, "--bogus", "1"} << "--bogus";
    QTest::newRow("no data") << QStringList{} << "--data";
    QTest::newRow("negative area")
        << QStringList{"--data", kTable1, "--bearing-area", "-5"} << "--bearing-area -5";
    QTest::newRow("area not a number")
        << QStringList{"--data", kTable1, "--bearing-area", "big"} << "--bearing-area 'big'";
    QTest::newRow("alpha 1") << QStringList{"--data", kTable1, "--alpha", "1"} << "--alpha 1";
    QTest::newRow("beta word") << QStringList{"--data", kTable1, "--beta", "half"}
                               << "--beta 'half'";
    QTest::newRow("outlier alpha")
        << QStringList{"--data", kTable1, "--outlier-alpha", "0.9"} << "--outlier-alpha";
    QTest::newRow("missing file") << QStringList{"--data", "/nonexistent.csv"}
                                  << "/nonexistent.csv: cannot open";
}

void TestCliFriction::badFlags() {
    QFETCH(QStringList, args);
    QFETCH(QString, message);
    const Run r = cli(args);
    QCOMPARE(r.code, 2);
    if (!r.err.contains(message.toUtf8())) qWarning("stderr: %s", r.err.constData());
    QVERIFY(r.err.contains(message.toUtf8()));
    QVERIFY(r.out.isEmpty());
}

void TestCliFriction::badCsv() {
    QTemporaryDir dir;
    const QString path = dir.filePath("bad.csv");
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write("configuration,cp_psi,test_no,delta_in,shear_kips\nBJ,100,1,0,12\nBJ,100,1,0.05,x\n");
    f.close();
    const Run r = cli({"--data", path});
    QCOMPARE(r.code, 2);
    QVERIFY(r.err.contains("line 3, column 'shear_kips': 'x' is not a number"));
}

QTEST_GUILESS_MAIN(TestCliFriction)
#include "tst_cli_friction.moc"
