// SPDX-License-Identifier: GPL-3.0-or-later
// kinstab-cli risk (docs/studies.md, "Risk"), run as a user would, on hazard files the test writes:
//  - a power-law hazard k0 x^-k: lambda_c = k0 theta^-k exp(k^2 beta^2 / 2) (Cornell et al.
//    2002), exact at any spacing; p in 50 years = 1 - exp(-50 lambda_c); both closed forms agree;
//  - a second-order hazard k0 exp(-k2 ln^2 x - k1 ln x) written as OpenQuake CSV (PoE in 50
//    years), USGS JSON and plain CSV gives the same numbers in each, and its second-order closed
//    form is the exact sqrt(q) k0^(1-q) lambda(theta)^q exp(q k1^2 beta^2 / 2) (Vamvatsikos 2013);
//  - --beta alone gives the risk-targeted median of the power law's closed form;
//  - --results: a fragility per set (the same lambda_c as --median/--beta with the median and
//    beta kinstab-cli fragility fits), --set K with bootstrap percentiles;
//  - bad input is exit 2 naming the flag, the file and line, and the value.
// Every test runs again under de_DE.UTF-8 (tests/CMakeLists.txt): numbers never follow it.

#include "CliRun.h"
#include "FileBytes.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <functional>

namespace {

QString num(double x) { // 17 significant digits, the C locale's syntax
    return QString::number(x, 'g', 17);
}

double relative(double got, double want) {
    return std::abs(got - want) / std::abs(want);
}

struct Point {
    double im, rate;
};

std::vector<Point> tabulate(const std::function<double(double)>& lambda, double lo, double hi,
                            int n) {
    std::vector<Point> p;
    for (int i = 0; i < n; ++i) {
        const double x = std::exp(std::log(lo) + (std::log(hi) - std::log(lo)) * i / (n - 1));
        p.push_back({x, lambda(x)});
    }
    return p;
}

QByteArray csvText(const std::vector<Point>& p, const QString& imt) {
    QString t = "# imt=" + imt + "\nim_g,annual_rate\n";
    for (const Point& q : p)
        t += num(q.im) + "," + num(q.rate) + "\n";
    return t.toUtf8();
}

QByteArray openQuakeText(const std::vector<Point>& p, const QString& imt) {
    QString t = "#,,,,\"generated_by='OpenQuake engine 3.16.0', kind='mean', "
                "investigation_time=50.0, imt='" +
                imt + "'\"\nlon,lat,depth";
    for (const Point& q : p)
        t += ",poe-" + num(q.im);
    t += "\n-117.25,34.5,0.0";
    for (const Point& q : p)
        t += "," + num(-std::expm1(-50 * q.rate));
    return (t + "\n").toUtf8();
}

QByteArray usgsText(const std::vector<Point>& p, const QString& imt) {
    QJsonArray x, y;
    for (const Point& q : p)
        x.append(q.im), y.append(q.rate);
    const QJsonObject metadata{{"imt", QJsonObject{{"value", imt}}}, {"xvalues", x}};
    const QJsonObject response{
        {"metadata", metadata},
        {"data", QJsonArray{QJsonObject{{"component", "Total"}, {"yvalues", y}}}}};
    return QJsonDocument(QJsonObject{{"response", QJsonArray{response}}}).toJson();
}

// One study row (the layout of core/io/StudyRowJson.cpp); critical < 0: censored at 3 g.
QByteArray row(int index, int cases, int set, double critical) {
    QJsonObject o{{"study", "0123456789abcdef"}, // one study's fingerprint on every row
                  {"case", index},
                  {"cases", cases},
                  {"set", set},
                  {"record", QString("r%1").arg(index)},
                  {"mu", 0.6},
                  {"tstar", 0.099},
                  {"limit", 1},
                  {"floor_period_s", QJsonValue()},
                  {"floor_damping", QJsonValue()},
                  {"measure", "pga"},
                  {"record_im_g", 0.3},
                  {"runs", 20},
                  {"limit_im_g", 3.0}};
    o["critical_im_g"] = critical < 0 ? QJsonValue() : QJsonValue(critical);
    o["critical_peak_g"] = critical < 0 ? QJsonValue() : QJsonValue(critical);
    return QJsonDocument(o).toJson(QJsonDocument::Compact) + "\n";
}

QJsonObject json(const Run& r) {
    return QJsonDocument::fromJson(r.out).object();
}

// k0 = 1e-4, k = 3: the power law of the first test.
double powerLaw(double x) {
    return 1e-4 * std::pow(x, -3.0);
}

// k0 = 2e-4, k1 = 2.2, k2 = 0.2 (resources/examples/hazard-second-order.csv).
double secondOrder(double x) {
    const double s = std::log(x);
    return 2e-4 * std::exp(-0.2 * s * s - 2.2 * s);
}

} // namespace

class TestCliRisk : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;
    QString path(const QString& name) const { return dir_.filePath(name); }
    QString write(const QString& name, const QByteArray& text) {
        writeBytes(path(name), text);
        return path(name);
    }

private slots:
    void initTestCase() {
        QVERIFY(dir_.isValid());
        write("power.csv", csvText(tabulate(powerLaw, 1e-3, 100, 50), "PGA"));
        const auto second = tabulate(secondOrder, std::exp(-5.0), std::exp(3.0), 1601);
        write("second.csv", csvText(second, "SA(1.0)"));
        write("hazard_curve-mean-SA(1.0)_1.csv", openQuakeText(second, "SA(1.0)"));
        write("second.json", usgsText(second, "SA1P0"));
        // Two sets of 8 records at the quantiles (i - 0.5)/8 of lognormals (median 0.8 g, beta
        // 0.4; median 1.2 g, beta 0.3), and a third set in which no record collapses.
        const double z[] = {-1.534, -0.887, -0.489, -0.157, 0.157, 0.489, 0.887, 1.534};
        QByteArray rows;
        for (int i = 0; i < 24; ++i) {
            const int set = i / 8;
            const double critical = set == 0   ? 0.8 * std::exp(0.4 * z[i % 8])
                                    : set == 1 ? 1.2 * std::exp(0.3 * z[i % 8])
                                               : -1.0;
            rows += row(i, 24, set, critical);
        }
        write("study.jsonl", rows);
        // Bad files for badInputIsExit2NamingWhere.
        write("empty.csv", "");
        write("increasing.csv", "im_g,annual_rate\n0.1,1e-2\n0.2,1e-3\n0.4,2e-3\n");
        write("nan.csv", "im_g,annual_rate\n0.1,1e-2\n0.2,NaN\n");
        write("poe1.csv", "#,\"investigation_time=50.0, imt='PGA'\"\nlon,lat,depth,poe-0.1,"
                          "poe-0.2\n1,2,0,1.0,0.5\n");
        write("pgv.csv", "#,\"investigation_time=50.0, imt='PGV'\"\nlon,lat,poe-1,poe-2\n1,2,0.5,"
                         "0.1\n");
    }

    void powerLawClosedForm() {
        // theta = 0.5 g, beta = 0.4: 1e-4 0.5^-3 exp(9 0.16 / 2) = 8e-4 exp(0.72) = 1.643099e-3.
        const Run r = cli({"risk", "--hazard", path("power.csv"), "--median", "0.5", "--beta",
                           "0.4", "--measure", "pga"});
        QVERIFY2(r.code == 0, r.err);
        const QJsonObject j = json(r);
        const double want = 1e-4 * std::pow(0.5, -3.0) * std::exp(9 * 0.16 / 2);
        QCOMPARE_LE(relative(j["lambda_c"].toDouble(), want), 1e-12);
        const QJsonObject p = j["p_collapse_in_years"].toObject();
        QCOMPARE(p["years"].toDouble(), 50.0);
        QCOMPARE_LE(relative(p["p"].toDouble(), -std::expm1(-50 * want)), 1e-12);
        QCOMPARE_LE(relative(j["closed_form_first_order"]["lambda_c"].toDouble(), want), 1e-12);
        QCOMPARE_LE(std::abs(j["closed_form_first_order"]["k"].toDouble() - 3), 1e-12);
        // A straight line in log-log: the fitted k2 is 0 and the second-order form the first.
        QCOMPARE_LE(std::abs(j["closed_form_second_order"]["k2"].toDouble()), 1e-10);
        QCOMPARE_LE(relative(j["closed_form_second_order"]["lambda_c"].toDouble(), want), 1e-9);
        const QJsonObject in = j["integration"].toObject();
        QVERIFY(in["rule"].toString().contains("log-log"));
        QCOMPARE(in["range_g"].toArray()[0].toDouble(), 1e-3);
        QCOMPARE(in["range_g"].toArray()[1].toDouble(), 100.0);
        QVERIFY(in["rate_beyond_curve"].toObject().contains("lambda_c_above_last_point"));
        QCOMPARE(j["hazard"]["intensity_measure"].toString(), QString("PGA"));
        QVERIFY(j["hazard"]["measure_checked"].toBool());
        // 1.64e-3 per year is above the 1 % in 50 years target, 2.0101e-4.
        QCOMPARE_LE(relative(j["target_rate"].toDouble(), 2.0100671707e-4), 1e-10);
        QVERIFY(!j["meets_target_rate"].toBool());
        // P(C) = 10 % at theta exp(-1.2815516 beta) = 0.5 exp(-0.5126206) = 0.29945 g.
        QCOMPARE_LE(
            relative(j["im_at_p10_g"].toDouble(), 0.5 * std::exp(-1.2815515655446004 * 0.4)),
            1e-14);
    }

    void threeFormatsAgreeWithTheSecondOrderForm() {
        // theta = 1 g, beta = 0.5: q = 1 / (1 + 2 0.2 0.25) = 1/1.1; lambda(1) = k0 = 2e-4;
        // sqrt(q) k0^(1-q) k0^q exp(q 2.2^2 0.25 / 2) = 2e-4 sqrt(1/1.1) exp(0.55) = 3.3088e-4.
        const double q = 1 / 1.1;
        const double exact = 2e-4 * std::sqrt(q) * std::exp(q * 2.2 * 2.2 * 0.25 / 2);
        double first = 0;
        for (const QString& f : {QString("second.csv"), QString("hazard_curve-mean-SA(1.0)_1.csv"),
                                 QString("second.json")}) {
            const Run r = cli({"risk", "--hazard", path(f), "--median", "1", "--beta", "0.5",
                               "--measure", "sa(1s/5%)", "--im", "0.6"});
            QVERIFY2(r.code == 0, r.err);
            const QJsonObject j = json(r);
            const double lc = j["lambda_c"].toDouble();
            if (first == 0) first = lc;
            QCOMPARE_LE(relative(lc, first), 1e-13); // one curve, three files
            // 1601 points over 8 in ln x: the log-log rule is within 2e-6 of the exact form
            // (tst_risk_integral shows the h^2 convergence).
            QCOMPARE_LE(relative(lc, exact), 2e-6);
            QCOMPARE_LE(relative(j["closed_form_second_order"]["lambda_c"].toDouble(), exact),
                        1e-9);
            QCOMPARE_LE(std::abs(j["closed_form_second_order"]["k1"].toDouble() - 2.2), 1e-9);
            QCOMPARE(j["hazard"]["intensity_measure"].toString(), QString("SA(1 s)"));
            // P(C | 0.6 g) = Phi(ln 0.6 / 0.5) = Phi(-1.021651) = 0.153473 (Python's math.erfc):
            // above 10 %.
            const QJsonObject at = j["p_collapse_at_im"].toObject();
            QCOMPARE_LE(std::abs(at["p"].toDouble() - 0.153473), 1e-6);
            QVERIFY(!at["within_target"].toBool());
        }
    }

    void riskTargetedMedian() {
        // Power law, beta 0.6, target -ln(0.99)/50: theta = (k0 exp(k^2 beta^2 / 2) / target)^(1/k)
        // = (1e-4 exp(1.62) / 2.0100672e-4)^(1/3) = 1.0246 g.
        const Run r = cli({"risk", "--hazard", path("power.csv"), "--beta", "0.6"});
        QVERIFY2(r.code == 0, r.err);
        const QJsonObject j = json(r);
        const double target = -std::log(0.99) / 50;
        const double want = std::cbrt(1e-4 * std::exp(9 * 0.36 / 2) / target);
        QCOMPARE_LE(relative(j["risk_targeted_median_g"].toDouble(), want), 1e-10);
        QCOMPARE_LE(relative(j["lambda_c"].toDouble(), target), 1e-9);
        QCOMPARE_LE(std::abs(j["p_collapse_in_years"]["p"].toDouble() - 0.01), 1e-10);
        QVERIFY(j["hazard"]["measure_checked"].toBool() == false); // no --measure
        // Another target rate.
        const Run r2 =
            cli({"risk", "--hazard", path("power.csv"), "--beta", "0.6", "--target-rate", "1e-5"});
        QVERIFY2(r2.code == 0, r2.err);
        QCOMPARE_LE(relative(json(r2)["risk_targeted_median_g"].toDouble(),
                             std::cbrt(1e-4 * std::exp(9 * 0.36 / 2) / 1e-5)),
                    1e-10);
    }

    void studyResults() {
        const Run all = cli({"risk", "--hazard", path("power.csv"), "--results",
                             path("study.jsonl"), "--bootstrap", "200"});
        QVERIFY2(all.code == 0, all.err);
        const QJsonArray sets = json(all)["sets"].toArray();
        QCOMPARE(sets.size(), 3);
        QCOMPARE(json(all)["measure"].toString(), QString("pga"));
        QVERIFY(sets[2].toObject().contains("no_fit"));
        // The same fit as kinstab-cli fragility, and the same lambda_c as --median/--beta.
        const Run frag = cli({"fragility", "--results", path("study.jsonl"), "--bootstrap", "0"});
        QVERIFY2(frag.code == 0, frag.err);
        const QJsonObject fit = json(frag)["sets"].toArray()[1].toObject();
        const Run one = cli({"risk", "--hazard", path("power.csv"), "--results",
                             path("study.jsonl"), "--set", "1", "--bootstrap", "200"});
        QVERIFY2(one.code == 0, one.err);
        const QJsonObject s = json(one);
        QCOMPARE(s["set"].toInt(), 1);
        QCOMPARE(s["fragility"]["median_g"].toDouble(), fit["median_g"].toDouble());
        QCOMPARE(s["fragility"]["beta"].toDouble(), fit["beta"].toDouble());
        const Run given =
            cli({"risk", "--hazard", path("power.csv"), "--median", num(fit["median_g"].toDouble()),
                 "--beta", num(fit["beta"].toDouble())});
        QVERIFY2(given.code == 0, given.err);
        QCOMPARE(s["lambda_c"].toDouble(), json(given)["lambda_c"].toDouble());
        QCOMPARE(sets[1].toObject()["lambda_c"].toDouble(), s["lambda_c"].toDouble());
        // Bootstrap percentiles over 200 resamples, ordered, around the estimate.
        const QJsonObject b = s["bootstrap"].toObject();
        QCOMPARE(b["resamples"].toInt(), 200);
        const QJsonObject l = b["lambda_c"].toObject();
        QVERIFY(l["p5"].toDouble() <= l["p50"].toDouble());
        QVERIFY(l["p50"].toDouble() <= l["p95"].toDouble());
        QVERIFY(l["p5"].toDouble() < s["lambda_c"].toDouble());
        QVERIFY(l["p95"].toDouble() > s["lambda_c"].toDouble());
        // The same seed draws the same resamples.
        const Run again = cli({"risk", "--hazard", path("power.csv"), "--results",
                               path("study.jsonl"), "--set", "1", "--bootstrap", "200"});
        QCOMPARE(again.out, one.out);
    }

    void badInputIsExit2NamingWhere_data() {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("message");
        const QString f = dir_.path() + "/";
        const QStringList fragility = {"--median", "1", "--beta", "0.5"};
        QTest::newRow("empty file") << (QStringList{"--hazard", f + "empty.csv"} + fragility)
                                    << "--hazard " + f + "empty.csv: the file is empty";
        QTest::newRow("rates increase")
            << (QStringList{"--hazard", f + "increasing.csv"} + fragility)
            << "--hazard " + f + "increasing.csv:4: annual rate 0.002 increases";
        QTest::newRow("NaN") << (QStringList{"--hazard", f + "nan.csv"} + fragility)
                             << "--hazard " + f + "nan.csv:3: annual rate nan must be a finite";
        QTest::newRow("PoE 1") << (QStringList{"--hazard", f + "poe1.csv"} + fragility)
                               << "--hazard " + f +
                                      "poe1.csv:3, column 'poe-0.1': PoE 1 is not below 1";
        QTest::newRow("unknown IMT")
            << (QStringList{"--hazard", f + "pgv.csv"} + fragility)
            << "--hazard " + f + "pgv.csv:1: unknown intensity measure imt='PGV'";
        QTest::newRow("measure against the study's")
            << QStringList{"--hazard", f + "second.csv", "--results", f + "study.jsonl"}
            << "--hazard " + f +
                   "second.csv:1: the hazard curve's intensity measure SA(1 s) is not the "
                   "fragility's PGA";
        QTest::newRow("measure against --measure")
            << (QStringList{"--hazard", f + "power.csv", "--measure", "sa(1s/5%)"} + fragility)
            << "--hazard " + f +
                   "power.csv:1: the hazard curve's intensity measure PGA is not the fragility's "
                   "SA(1 s)";
        QTest::newRow("USGS measure")
            << (QStringList{"--hazard", f + "second.json", "--measure", "PGA"} + fragility)
            << "--hazard " + f +
                   "second.json: the hazard file has no curve for the fragility's intensity "
                   "measure PGA (it holds 'SA1P0')";
        QTest::newRow("median without beta")
            << QStringList{"--hazard", f + "power.csv", "--median", "1"}
            << "--median '1': needs --beta";
        QTest::newRow("beta 0") << QStringList{"--hazard", f + "power.csv", "--beta", "0"}
                                << "--beta '0': must be >= 1e-04 and at most 5";
        QTest::newRow("years") << (QStringList{"--hazard", f + "power.csv", "--years", "-5"} +
                                   fragility)
                               << "--years '-5': must be > 0 and at most 10000 years";
        QTest::newRow("no fragility") << QStringList{"--hazard", f + "power.csv"}
                                      << "--results: give --results, or --median and --beta";
        QTest::newRow("set without results")
            << (QStringList{"--hazard", f + "power.csv", "--set", "1"} + fragility)
            << "--set '1': needs --results";
        QTest::newRow("set not in the results")
            << QStringList{"--hazard",        f + "power.csv", "--results",
                           f + "study.jsonl", "--set",         "7"}
            << "--set '7': is no parameter set of the results (3 sets, numbered from 0)";
        QTest::newRow("set without a fit")
            << QStringList{"--hazard", f + "power.csv", "--results", f + "study.jsonl", "--set",
                           "2",        "--bootstrap",   "0"}
            << "--set '2': has no fitted fragility";
        QTest::newRow("site of a CSV")
            << (QStringList{"--hazard", f + "power.csv", "--site", "1,2"} + fragility)
            << "--hazard " + f + "power.csv: a site is given, but a csv hazard file";
        QTest::newRow("site text")
            << (QStringList{"--hazard", f + "power.csv", "--site", "1;2"} + fragility)
            << "--site '1;2': expected LON,LAT in degrees";
        QTest::newRow("unknown measure")
            << (QStringList{"--hazard", f + "power.csv", "--measure", "pgv"} + fragility)
            << "--measure 'pgv': 'pgv' is no measure a hazard curve is given in";
    }
    void badInputIsExit2NamingWhere() {
        QFETCH(QStringList, args);
        QFETCH(QString, message);
        const Run r = cli(QStringList{"risk"} + args);
        QCOMPARE(r.code, 2);
        QVERIFY2(r.err.contains(message.toUtf8()), r.err);
        QVERIFY(r.out.isEmpty());
    }
};

QTEST_GUILESS_MAIN(TestCliRisk)
#include "tst_cli_risk.moc"
