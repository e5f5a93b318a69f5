// SPDX-License-Identifier: GPL-3.0-or-later
// The study inputs beyond records x mu x t* x floor filter (docs/studies.md), run as a user would:
//  - records[].scale: the record as given in the suite is the file times its scale; the critical
//    intensity does not depend on it, the intensity as given and the margin do (linearity);
//  - parameters.levels of the study's building: for a one-storey building, level 1's motion is
//    the floor filter's of the same period and damping (modal superposition with one mode, a
//    different code path), so the critical intensities agree;
//  - parameters.motion "fitted_sine": the critical peak is kinstab-cli critical's A_crit of the
//    enveloped sine with the envelope and frequency kinstab-cli record reports for the record;
//    a motion of fewer than 3 half cycles has no fit and its row says why;
//  - a bad scale, level or motion is exit 2 naming the field and the value;
//  - records folders (issue 31): an excluded entry is never looked at (a self-looping symlink
//    among them does no harm), a matched symlink that loops or leads out of the folder is exit 2
//    naming it, one to a file in the folder is a record; a path with a NUL is refused, not cut.

#include "CliRun.h"
#include "FileBytes.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QtTest>

#include <unistd.h>

#include <array>
#include <cmath>

namespace {

const QByteArray kElc = KINSTAB_SOURCE_DIR "/resources/records/RSN6_IMPVALL.I_I-ELC180.AT2";
const QByteArray kSearch =
    "\"search\": {\"max_g\": 2, \"scan_step_g\": 0.05, \"tolerance_g\": 1e-3}";
constexpr double kTolerance = 1e-3; // g, the search's tolerance_g above

QByteArray study(const QByteArray& records, const QByteArray& rest) {
    return "{\"format\": \"kinstab-study\", \"version\": 1, \"records\": [" + records + "], " +
           rest + ", " + kSearch + "}";
}

QList<QJsonObject> rowsOf(const QByteArray& jsonl) {
    QList<QJsonObject> rows;
    for (const QByteArray& l : jsonl.trimmed().split('\n'))
        rows.push_back(QJsonDocument::fromJson(l).object());
    return rows;
}

// A one-storey building of period 0.5 s, 5 % modal damping.
const QByteArray kOneStorey =
    "\"building\": {\"stories\": 1, \"height\": 12, \"plan_dimension\": 50, \"period_s\": 0.5}, "
    "\"floors\": {\"damping\": 0.05}";

} // namespace

class TestCliStudyInputs : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

    QString write(const QString& name, const QByteArray& text) {
        const QString path = dir_.filePath(name);
        writeBytes(path, text);
        return path;
    }
    QList<QJsonObject> runStudy(const QByteArray& spec) {
        const Run r = cli({"study", "--spec", write("spec.json", spec), "--threads", "1"});
        if (r.code != 0) qWarning() << r.err;
        return r.code == 0 ? rowsOf(r.out) : QList<QJsonObject>{};
    }
    QByteArray refusal(const QByteArray& spec) {
        const Run r = cli({"study", "--spec", write("bad.json", spec)});
        return r.code == 2 ? r.err : "exit " + QByteArray::number(r.code) + ": " + r.out;
    }

private slots:
    void scaleLeavesTheCriticalIntensityAndScalesTheIntensityAsGiven() {
        const QByteArray records = "{\"path\": \"" + kElc + "\"}, {\"path\": \"" + kElc +
                                   "\", \"scale\": 2}, {\"path\": \"" + kElc + "\", \"scale\": 5}";
        const auto rows = runStudy(study(records, "\"parameters\": {\"mu\": [0.5]}"));
        QCOMPARE(rows.size(), 3);
        const double im = rows[0]["record_im_g"].toDouble();
        const double critical = rows[0]["critical_im_g"].toDouble();
        QVERIFY(critical > 0);
        for (int k = 0; k < 3; ++k) {
            const double scale = std::array{1.0, 2.0, 5.0}[k];
            // The search scales the record anyway: the same critical intensity at any scale;
            // the record as given is the file times its scale (the record is linear in it).
            QCOMPARE(rows[k]["scale"].toDouble(), scale);
            QCOMPARE(rows[k]["critical_im_g"].toDouble(), critical);
            QCOMPARE(rows[k]["im_as_given_g"].toDouble(), scale * im);
            QCOMPARE(rows[k]["margin"].toDouble(), critical / (scale * im));
            QCOMPARE(rows[k]["collapses_as_given"].toBool(), critical <= scale * im);
        }
        // ELC180's PGA 0.28 g; it collapses the slab (mu 0.5) at 1.27 g: only x5 falls as given.
        QVERIFY(!rows[1]["collapses_as_given"].toBool() && rows[2]["collapses_as_given"].toBool());
        const QString results = write("scaled.jsonl", QByteArray());
        QVERIFY(cli({"study", "--spec", dir_.filePath("spec.json"), "-o", results}).code == 0);
        const Run f = cli({"fragility", "--results", results, "--bootstrap", "20"});
        QVERIFY2(f.code == 0, f.err);
        const QJsonObject set = QJsonDocument::fromJson(f.out)["sets"].toArray()[0].toObject();
        QCOMPARE(set["collapsed_as_given_fraction"].toDouble(), 1.0 / 3.0);
        const Run csv =
            cli({"fragility", "--results", results, "--bootstrap", "20", "--format", "csv"});
        QVERIFY2(csv.out.split('\n')[0].endsWith(",collapsed_as_given_fraction"), csv.out);
    }
    void scaleOfAFolderAppliesToEachFile() {
        const auto rows = runStudy(study("{\"path\": \"" KINSTAB_SOURCE_DIR
                                         "/resources/records\", \"include\": [\"RSN68*.AT2\"], "
                                         "\"exclude\": [\"*UP*\"], \"scale\": 3}",
                                         "\"parameters\": {\"mu\": [0.5]}"));
        QCOMPARE(rows.size(), 2);
        for (const QJsonObject& r : rows)
            QCOMPARE(r["im_as_given_g"].toDouble(), 3 * r["record_im_g"].toDouble());
    }
    void studiesWithoutTheNewInputsWriteNoNewFields() {
        const auto rows = runStudy(study("{\"path\": \"" + kElc + "\"}", "\"name\": \"plain\""));
        QCOMPARE(rows.size(), 1);
        for (const char* key : {"scale", "im_as_given_g", "margin", "level", "motion", "no_fit"})
            QVERIFY2(!rows[0].contains(key), key);
    }
    void badScaleNamesTheField_data() {
        QTest::addColumn<QByteArray>("value");
        QTest::addColumn<QByteArray>("named");
        QTest::newRow("zero") << QByteArray("0") << QByteArray("records[0].scale = 0: must be");
        QTest::newRow("negative") << QByteArray("-1") << QByteArray("records[0].scale = -1:");
        QTest::newRow("NaN") << QByteArray("\"NaN\"") << QByteArray("records[0].scale = 'NaN':");
        QTest::newRow("text") << QByteArray("\"x\"") << QByteArray("records[0].scale = 'x':");
        QTest::newRow("huge") << QByteArray("101") << QByteArray("records[0].scale = 101:");
    }
    void badScaleNamesTheField() {
        QFETCH(QByteArray, value);
        QFETCH(QByteArray, named);
        const QByteArray err =
            refusal(study("{\"path\": \"" + kElc + "\", \"scale\": " + value + "}", "\"a\": 0"));
        QVERIFY2(err.contains(named), err);
    }
    void levelOfAOneStoreyBuildingIsTheFloorFilter() {
        const auto rows = runStudy(
            study("{\"path\": \"" + kElc + "\"}",
                  kOneStorey + ", \"parameters\": {\"mu\": [0.5, 0.7], \"levels\": [1], "
                               "\"floor_filter\": {\"periods_s\": [0.5], \"dampings\": [0.05]}}"));
        QCOMPARE(rows.size(), 4); // mu x (floor filter, then level 1)
        for (int k : {0, 2}) {
            const QJsonObject& filter = rows[k];
            const QJsonObject& level = rows[k + 1];
            QCOMPARE(filter["floor_period_s"].toDouble(), 0.5);
            QVERIFY(!filter.contains("level"));
            QCOMPARE(level["level"].toInt(), 1);
            QVERIFY(level["floor_period_s"].isNull());
            QCOMPARE(level["set"].toInt(), filter["set"].toInt() + 1);
            QVERIFY(!filter["critical_im_g"].isNull());
            const double perPeak =
                filter["critical_im_g"].toDouble() / filter["critical_peak_g"].toDouble();
            QCOMPARE_LE(std::abs(level["critical_peak_g"].toDouble() -
                                 filter["critical_peak_g"].toDouble()),
                        kTolerance);
            QCOMPARE_LE(
                std::abs(level["critical_im_g"].toDouble() - filter["critical_im_g"].toDouble()),
                kTolerance * perPeak);
        }
    }
    void badLevelNamesTheField_data() {
        QTest::addColumn<QByteArray>("rest");
        QTest::addColumn<QByteArray>("named");
        QTest::newRow("zero") << kOneStorey + ", \"parameters\": {\"levels\": [0]}"
                              << QByteArray("parameters.levels[0] = 0: must be a level from 1");
        QTest::newRow("above") << kOneStorey + ", \"parameters\": {\"levels\": [1, 2]}"
                               << QByteArray("parameters.levels[1] = 2: must be a level from 1");
        QTest::newRow("no building") << QByteArray("\"parameters\": {\"levels\": [1]}")
                                     << QByteArray("parameters.levels: needs the study's");
        QTest::newRow("slab level")
            << kOneStorey.left(kOneStorey.size() - 1) + ", \"slab_level\": 1}"
            << QByteArray("floors.slab_level");
        QTest::newRow("building") << QByteArray("\"building\": {\"stories\": 0, \"height\": 12, "
                                                "\"plan_dimension\": 50}")
                                  << QByteArray("building.stories = 0");
    }
    void badLevelNamesTheField() {
        QFETCH(QByteArray, rest);
        QFETCH(QByteArray, named);
        const QByteArray err = refusal(study("{\"path\": \"" + kElc + "\"}", rest));
        QVERIFY2(err.contains(named), err);
    }
    // Issue 31: the search's and the parameters' rules are core's declarations, named by the
    // spec's own keys (max_g, not check.max_amplitude; a tiny max_g blames max_g, not the step).
    void badSearchAndParametersNameTheSpecKey_data() {
        QTest::addColumn<QByteArray>("spec");
        QTest::addColumn<QByteArray>("named");
        const QByteArray head = "{\"format\": \"kinstab-study\", \"version\": 1, \"records\": "
                                "[{\"path\": \"" +
                                kElc + "\"}], ";
        QTest::newRow("max_g -1") << head + "\"search\": {\"max_g\": -1}}"
                                  << QByteArray("search.max_g = -1 g: largest amplitude searched");
        QTest::newRow("max_g 1e-300")
            << head + "\"search\": {\"max_g\": 1e-300}}" << QByteArray("search.max_g = 1e-300 g:");
        QTest::newRow("a million scan points")
            << head + "\"search\": {\"max_g\": 1000, \"scan_step_g\": 0.001}}"
            << QByteArray("search.scan_step_g = 0.001 g: at most 100000 scan points");
        QTest::newRow("tstar 1e-300") << head + "\"parameters\": {\"tstar\": [1e-300]}}"
                                      << QByteArray("parameters.tstar[0] = 1e-300: t* = sqrt");
        QTest::newRow("mu 1e-300") << head + "\"parameters\": {\"mu\": [0.6, 1e-300]}}"
                                   << QByteArray("parameters.mu[1] = 1e-300: friction coefficient");
    }
    void badSearchAndParametersNameTheSpecKey() {
        QFETCH(QByteArray, spec);
        QFETCH(QByteArray, named);
        const QByteArray err = refusal(spec);
        QVERIFY2(err.contains(named), err);
    }
    void fittedSineIsTheCriticalCommandsEnvelopedSine() {
        const auto rows = runStudy(study("{\"path\": \"" + kElc + "\"}",
                                         "\"parameters\": {\"mu\": [0.5], \"motion\": "
                                         "[\"record\", \"fitted_sine\"]}"));
        QCOMPARE(rows.size(), 2);
        QCOMPARE(rows[0]["motion"].toString(), QString("record"));
        QCOMPARE(rows[1]["motion"].toString(), QString("fitted_sine"));
        QCOMPARE(rows[1]["set"].toInt(), 1);
        // The envelope and the dominant frequency as kinstab-cli record reports them.
        const Run rec = cli({"record", "--file", kElc, "--peaks", "1"});
        QVERIFY2(rec.code == 0, rec.err);
        const QJsonObject j = QJsonDocument::fromJson(rec.out).object();
        const QJsonObject env = j["envelope"].toObject();
        const double f = j["spectrum"]["peaks"][0]["frequency_hz"].toDouble();
        const Run crit =
            cli({"critical", "--frequencies", QString::number(f, 'g', 17), "--alpha",
                 QString::number(env["alpha"].toDouble(), 'g', 17), "--beta",
                 QString::number(env["beta"].toDouble(), 'g', 17), "--mu", "0.5", "--max-amplitude",
                 "2", "--scan-step", "0.05", "--tolerance", "1e-3"});
        QVERIFY2(crit.code == 0, crit.err);
        const double aCrit = QJsonDocument::fromJson(crit.out)["a_crit"][0].toDouble();
        QVERIFY(aCrit > 0);
        QCOMPARE_LE(std::abs(rows[1]["critical_peak_g"].toDouble() - aCrit), kTolerance);
        // Scaled like the record it stands for: IM x A_crit / the fitted envelope's peak.
        QCOMPARE_LE(std::abs(rows[1]["critical_im_g"].toDouble() -
                             rows[1]["record_im_g"].toDouble() * aCrit / env["peak_g"].toDouble()),
                    1e-9);
    }
    void aPulseHasNoFitAndSaysWhy() {
        // One half sine of 0.3 g over 2 s: a single half-cycle peak, no envelope to fit.
        QByteArray at2 = "PEER NGA STRONG MOTION DATABASE RECORD\nTest pulse\n"
                         "ACCELERATION TIME SERIES IN UNITS OF G\nNPTS=   200, DT=   .0100 SEC\n";
        for (int i = 0; i < 200; ++i)
            at2 += QByteArray::number(0.3 * std::sin(M_PI * i / 199.0), 'E', 7) +
                   (i % 5 == 4 ? "\n" : "  ");
        write("pulse.AT2", at2);
        const QByteArray spec =
            study("{\"path\": \"pulse.AT2\"}", "\"parameters\": {\"motion\": [\"fitted_sine\"]}");
        const Run r =
            cli({"study", "--spec", write("pulse.json", spec), "-o", dir_.filePath("pulse.jsonl")});
        QVERIFY2(r.code == 0, r.err);
        const QByteArray text = readAll(dir_.filePath("pulse.jsonl"));
        QVERIFY(!text.contains("nan") && !text.contains("NaN"));
        const QJsonObject row = rowsOf(text)[0];
        QVERIFY2(row["no_fit"].toString().contains("half-cycle"), text);
        QVERIFY(row["critical_im_g"].isNull());
        const Run f = cli({"fragility", "--results", dir_.filePath("pulse.jsonl")});
        QVERIFY2(f.code == 0, f.err);
        const QJsonObject set = QJsonDocument::fromJson(f.out)["sets"].toArray()[0].toObject();
        QCOMPARE(set["records_without_fit"].toInt(), 1);
        QCOMPARE(set["records"].toInt(), 0);
    }
    void theLevelsExampleRuns() {
        // resources/examples/study-levels.json: 6 records x levels {1, 8, 16} x 2 motions.
        const QString spec = KINSTAB_SOURCE_DIR "/resources/examples/study-levels.json";
        const Run count = cli({"study", "--spec", spec, "--count"});
        QCOMPARE(count.out, QByteArray("36\n"));
        const Run r = cli({"study", "--spec", spec});
        QVERIFY2(r.code == 0, r.err);
        const auto rows = rowsOf(r.out);
        QCOMPARE(rows.size(), 36);
        QCOMPARE(rows[0]["level"].toInt(), 1);
        QCOMPARE(rows[6]["motion"].toString(), QString("fitted_sine"));
        QCOMPARE(rows[35]["level"].toInt(), 16);
        // Below mu nothing slips: a collapse needs a driving peak of at least mu (0.6).
        for (const QJsonObject& row : rows)
            QVERIFY(row["critical_peak_g"].isNull() || row["critical_peak_g"].toDouble() >= 0.6);
    }
    void badMotionNamesTheField() {
        const QByteArray rec = "{\"path\": \"" + kElc + "\"}";
        QByteArray err = refusal(study(rec, "\"parameters\": {\"motion\": [\"sine\"]}"));
        QVERIFY2(err.contains("parameters.motion[0] = 'sine'"), err);
        err = refusal(study(rec, "\"parameters\": {\"motion\": [\"record\", \"record\"]}"));
        QVERIFY2(err.contains("parameters.motion[1] = 'record': appears twice"), err);
    }
    void recordFoldersAndTheirSymlinks() {
        QTemporaryDir d;
        const QString folder = d.filePath("records");
        QVERIFY(QDir().mkpath(folder));
        QVERIFY(QFile::copy(QString(kElc), folder + "/ELC180.AT2"));
        QCOMPARE(::symlink("loop.AT2", qPrintable(folder + "/loop.AT2")), 0); // a link to itself
        const QString spec = d.filePath("spec.json");
        const auto withFolder = [&](const QByteArray& patterns) {
            writeBytes(spec, study("{\"path\": \"records\"" + patterns + "}",
                                   "\"parameters\": {\"mu\": [0.5]}"));
            return cli({"study", "--spec", spec, "--threads", "1"});
        };
        Run r = withFolder(", \"exclude\": [\"loop*\"]");
        QVERIFY2(r.code == 0, r.err.constData());
        QCOMPARE(r.out.count('\n'), 1);
        r = withFolder("");
        QCOMPARE(r.code, 2);
        QVERIFY2(r.err.contains("records[0].path = 'loop.AT2': a symlink that cannot be followed"),
                 r.err.constData());
        QVERIFY(QFile::remove(folder + "/loop.AT2"));
        QCOMPARE(::symlink(kElc.constData(), qPrintable(folder + "/outside.AT2")), 0);
        r = withFolder("");
        QCOMPARE(r.code, 2);
        QVERIFY2(r.err.contains("'outside.AT2': a symlink out of the folder"), r.err.constData());
        QVERIFY(QFile::remove(folder + "/outside.AT2"));
        QCOMPARE(::symlink("ELC180.AT2", qPrintable(folder + "/inside.AT2")), 0);
        r = withFolder("");
        QVERIFY2(r.code == 0, r.err.constData());
        QCOMPARE(r.out.count('\n'), 2);
    }
    void aPathWithNulIsRefused() {
        // "ELC180.AT2\u0000junk" names no file; cut at the NUL it would name ELC180.AT2.
        const QByteArray rec = "{\"path\": \"" + kElc + "\\u0000junk\"}";
        const QByteArray err = refusal(study(rec, "\"parameters\": {\"mu\": [0.5]}"));
        QVERIFY2(err.contains("records[0].path: the path contains a NUL character"), err);
    }
};

QTEST_GUILESS_MAIN(TestCliStudyInputs)
#include "tst_cli_study_inputs.moc"
