// SPDX-License-Identifier: GPL-3.0-or-later
// kinstab-cli codes | check as a user runs them (docs/user-guide.md "The command line"): the
// paper's numbers from the example project and from building flags, and exit 2 with the bad flag
// named.

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

#include "CliRun.h"

namespace {
const QString kExample = KINSTAB_SOURCE_DIR "/resources/examples/paper-16-story.json";
void near(double got, double want, double tol) {
    QVERIFY2(std::abs(got - want) <= tol,
             qPrintable(QString("got %1, want %2").arg(got, 0, 'g', 12).arg(want)));
}
const QStringList kPaperFlags = {"--stories",      "16",    "--height-ft", "177",
                                 "--dimension-ft", "78.62", "--system",    "dual_frame_wall",
                                 "--zone",         "4",     "--k-factor",  "0.8",
                                 "--av",           "0.4",   "--aa",        "0.4",
                                 "--soil",         "S3",    "--r",         "5.5"};
} // namespace

class TestCliCodes : public QObject {
    Q_OBJECT
private slots:
    void exampleProject() {
        // Furgerson 1980 eqs. 9, 14, 16, 21; docs/codes.md §1 and §7.2 for F_t, ASCE 7-22 and EC8.
        const Run r = cli({"codes", "--project", kExample});
        QCOMPARE(r.code, 0);
        const QJsonObject j = QJsonDocument::fromJson(r.out).object();
        QCOMPARE(j.keys(),
                 QStringList({"asce7_22", "atc306", "ec8", "kinstab_version", "ubc1976"}));
        const QJsonObject u = j["ubc1976"].toObject();
        for (const char* key : {"base_shear_coefficient", "period_s", "top_ratio", "story_forces",
                                "trail", "top_ratio_without_ft"})
            QVERIFY2(u.contains(key), key);
        near(u["base_shear_coefficient"].toDouble(), 0.080, 1e-12);
        near(u["period_s"].toDouble(), 1.0, 0);
        near(u["top_ratio_without_ft"].toDouble(), 0.140047, 5e-7);
        near(u["top_ratio"].toDouble(), 0.229647, 5e-7);
        const QJsonArray forces = u["story_forces"].toArray();
        QCOMPARE(forces.size(), 16);
        near(forces.last().toDouble(), u["top_ratio"].toDouble(), 0); // top last
        const QJsonObject a = j["atc306"].toObject();
        near(a["base_shear_coefficient"].toDouble(), 0.13091, 5e-6);
        near(a["top_ratio"].toDouble(), 0.275, 5e-4);
        QVERIFY(!a.contains("top_ratio_without_ft"));
        near(j["asce7_22"].toObject()["top_ratio"].toDouble(), 0.210081, 5e-7);
        near(j["ec8"].toObject()["top_ratio"].toDouble(), 0.176923, 5e-7);
        // Every trail entry has name, symbol, value, clause.
        for (const QJsonValue& t : u["trail"].toArray())
            for (const char* key : {"name", "symbol", "value", "clause"})
                QVERIFY2(t.toObject().contains(key), key);
    }
    void buildingFlagsEstimatePeriod() {
        // No --period: T = 0.05 · 177/sqrt(78.62) = 0.998106 s (eq. 7) for UBC and ATC alike.
        const Run r = cli(QStringList{"codes"} + kPaperFlags);
        QCOMPARE(r.code, 0);
        const QJsonObject j = QJsonDocument::fromJson(r.out).object();
        QCOMPARE(j.keys(), QStringList({"atc306", "kinstab_version", "ubc1976"}));
        near(j["ubc1976"].toObject()["period_s"].toDouble(), 0.998106, 5e-7);
        near(j["atc306"].toObject()["period_s"].toDouble(), 0.998106, 5e-7);
        near(j["ubc1976"].toObject()["base_shear_coefficient"].toDouble(), 0.080, 5e-4);
    }
    void buildingFlagsWithPaperPeriod() {
        const Run r = cli(QStringList{"codes", "--period", "1.0"} + kPaperFlags);
        QCOMPARE(r.code, 0);
        const QJsonObject j = QJsonDocument::fromJson(r.out).object();
        near(j["ubc1976"].toObject()["top_ratio_without_ft"].toDouble(), 0.140047, 5e-7);
        near(j["atc306"].toObject()["top_ratio"].toDouble(), 0.27502, 5e-6);
    }
    void metresGiveTheSameNumbers() {
        const Run r = cli({"codes", "--stories", "16", "--height-m", "53.9496", "--dimension-m",
                           "23.963376", "--zone", "4", "--k-factor", "0.8"});
        QCOMPARE(r.code, 0);
        near(QJsonDocument::fromJson(r.out).object()["ubc1976"].toObject()["period_s"].toDouble(),
             0.998106, 5e-7);
    }
    void check() {
        // Chapter V eq. 22: A_crit ≈ 0.95 g at 1 Hz, far above 0.140/0.2296 and 0.275.
        const Run r = cli({"check", "--project", kExample});
        QCOMPARE(r.code, 0);
        const QJsonObject codes = QJsonDocument::fromJson(r.out).object()["codes"].toObject();
        QCOMPARE(codes.size(), 4);
        for (const QString& k : codes.keys()) {
            const QJsonObject c = codes[k].toObject();
            QCOMPARE(c["verdict"].toString(), QString("overstress governs"));
            QVERIFY(c["a_crit"].toDouble() >= 0.95 && c["a_crit"].toDouble() <= 0.98);
            near(c["margin"].toDouble(), c["a_crit"].toDouble() / c["ratio"].toDouble(), 1e-12);
        }
        near(codes["ubc1976"].toObject()["ratio_without_ft"].toDouble(), 0.140047, 5e-7);
    }
    void badInput_data() {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("mention");
        const QStringList base = {"codes", "--stories",      "16",   "--height-ft",
                                  "177",   "--dimension-ft", "78.62"};
        QTest::newRow("zone 5") << base + QStringList{"--zone", "5", "--k-factor", "0.8"}
                                << "--zone";
        QTest::newRow("zone 7") << base + QStringList{"--zone", "7", "--k-factor", "0.8"}
                                << "ubc1976.zone = 7";
        QTest::newRow("negative height")
            << QStringList{"codes", "--stories", "16", "--height-ft", "-177", "--dimension-ft",
                           "78.62", "--zone",    "4",  "--k-factor",  "0.8"}
            << "--height-ft -177";
        QTest::newRow("T = 0") << base + QStringList{"--period", "0",          "--zone",
                                                     "4",        "--k-factor", "0.8"}
                               << "--period 0";
        QTest::newRow("R = 0") << base + QStringList{"--av",   "0.4", "--aa", "0.4",
                                                     "--soil", "S3",  "--r",  "0"}
                               << "--r: atc306.r = 0";
        QTest::newRow("NaN") << base + QStringList{"--zone", "4", "--k-factor", "nan"}
                             << "--k-factor 'nan'";
        QTest::newRow("soil S4") << base + QStringList{"--av",   "0.4", "--aa", "0.4",
                                                       "--soil", "S4",  "--r",  "5"}
                                 << "--soil 'S4'";
        QTest::newRow("no code") << base << "no code selected";
        QTest::newRow("k without zone")
            << base + QStringList{"--k-factor", "0.8"} << "--k-factor applies to UBC 1976";
        QTest::newRow("missing K") << base + QStringList{"--zone", "4"} << "--k-factor";
        QTest::newRow("project and flags")
            << QStringList{"codes", "--project", kExample, "--zone", "4"} << "exclude each other";
        QTest::newRow("missing project file")
            << QStringList{"check", "--project", "/nonexistent/p.json"}
            << "--project /nonexistent/p.json";
        QTest::newRow("check without project") << QStringList{"check"} << "--project";
    }
    void badInput() {
        QFETCH(QStringList, args);
        QFETCH(QString, mention);
        const Run r = cli(args);
        QCOMPARE(r.code, 2);
        QVERIFY2(QString::fromUtf8(r.err).contains(mention), r.err.constData());
        QVERIFY(r.out.isEmpty()); // nothing computed from bad input
    }
    void corruptProject() {
        QTemporaryDir dir;
        const QString path = dir.filePath("p.json");
        QFile in(kExample);
        QVERIFY(in.open(QIODevice::ReadOnly));
        const QByteArray text = in.readAll();
        QFile out(path);
        QVERIFY(out.open(QIODevice::WriteOnly));
        out.write(text.left(text.size() / 3)); // truncated
        out.close();
        const Run r = cli({"check", "--project", path});
        QCOMPARE(r.code, 2);
        QVERIFY2(QString::fromUtf8(r.err).contains("truncated or corrupt"), r.err.constData());
    }
};

QTEST_APPLESS_MAIN(TestCliCodes)
#include "tst_cli_codes.moc"
