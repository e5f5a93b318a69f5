// SPDX-License-Identifier: GPL-3.0-or-later
// kinstab-cli study, merge and fragility (docs/studies.md), run as a user would:
//  - the rows are the same bytes on 1 and 2 threads, and shards merged in any order are the
//    same bytes as the unsharded run;
//  - GNU parallel running the shards and the merge (examples/parallel/run-study.sh) gives the
//    same bytes; the Slurm scripts in examples/slurm pass bash -n;
//  - each row names its inputs and its critical intensity (or is censored at the limit);
//  - a bad study file, shard or results file is exit 2 with the field named; shards of two studies
//    of the same size are refused naming both fingerprints (issue 31), and a shard out of case
//    order is named at its line, not reported as a missing case.

#include "CliRun.h"
#include "FileBytes.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

namespace {

const QString kSpec = QStringLiteral(KINSTAB_TEST_DATA "/study/small-study.json");

QString writeSpec(const QTemporaryDir& dir, const QByteArray& text) {
    const QString path = dir.filePath("bad.json");
    writeBytes(path, text);
    return path;
}

// A minimal valid study whose one key is replaced by `patch` (a JSON member text).
QByteArray studyWith(const QByteArray& patch) {
    const QByteArray records = "\"records\": [{\"path\": \"" KINSTAB_SOURCE_DIR
                               "/resources/records/RSN6_IMPVALL.I_I-ELC180.AT2\"}]";
    return "{\"format\": \"kinstab-study\", \"version\": 1, " + records + ", " + patch + "}";
}

} // namespace

class TestCliStudy : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;
    QByteArray whole_;

private slots:
    void initTestCase() {
        QVERIFY(dir_.isValid());
        const Run r =
            cli({"study", "--spec", kSpec, "--threads", "1", "-o", dir_.filePath("all.jsonl")});
        QVERIFY2(r.code == 0, r.err);
        whole_ = readAll(dir_.filePath("all.jsonl"));
    }
    void countsTheCases() {
        // 3 records (ELC180, PEL090, PEL180) x 2 mu x 1 t* x (ground + one floor filter).
        const Run r = cli({"study", "--spec", kSpec, "--count"});
        QCOMPARE(r.code, 0);
        QCOMPARE(r.out, QByteArray("12\n"));
        QCOMPARE(whole_.count('\n'), 12);
    }
    void rowsNameTheirInputs() {
        const QList<QByteArray> lines = whole_.trimmed().split('\n');
        const QJsonObject first = QJsonDocument::fromJson(lines[0]).object();
        QCOMPARE(first["case"].toInt(), 0);
        QCOMPARE(first["cases"].toInt(), 12);
        QCOMPARE(first["record"].toString(),
                 QString("../../../resources/records/RSN6_IMPVALL.I_I-ELC180.AT2"));
        QCOMPARE(first["mu"].toDouble(), 0.5);
        QVERIFY(first["floor_period_s"].isNull()); // ground first, then the floor filter
        QCOMPARE(first["measure"].toString(), QString("sa(0.5s/5%)"));
        const QJsonObject fourth = QJsonDocument::fromJson(lines[3]).object();
        QCOMPARE(fourth["floor_period_s"].toDouble(), 0.5);
        QCOMPARE(fourth["set"].toInt(), 1);
        QVERIFY(!whole_.contains("seconds")); // no timing: reruns are the same bytes
        for (const QByteArray& l : lines) {
            const QJsonObject o = QJsonDocument::fromJson(l).object();
            const double perPeak = o["record_im_g"].toDouble() / 1.0;
            QVERIFY(perPeak > 0);
            if (o["critical_im_g"].isNull()) continue;
            // The slab cannot slip below mu: the critical peak of the driving motion is >= mu.
            QVERIFY(o["critical_peak_g"].toDouble() >= o["mu"].toDouble());
            QVERIFY(o["critical_im_g"].toDouble() <= o["limit_im_g"].toDouble());
        }
    }
    void threadsDoNotChangeTheBytes() {
        const Run r = cli({"study", "--spec", kSpec, "--threads", "2"});
        QVERIFY2(r.code == 0, r.err);
        QCOMPARE(r.out, whole_);
    }
    void shardsMergeToTheUnshardedRun() {
        QStringList shards;
        for (int k = 1; k <= 5; ++k) {
            const QString out = dir_.filePath(QString("shard-%1.jsonl").arg(k));
            const Run r = cli({"study", "--spec", kSpec, "--shard", QString("%1/5").arg(k),
                               "--threads", "1", "-o", out});
            QVERIFY2(r.code == 0, r.err);
            shards.prepend(out); // any order
        }
        const QString merged = dir_.filePath("merged.jsonl");
        const Run m = cli(QStringList{"merge"} + shards + QStringList{"-o", merged});
        QVERIFY2(m.code == 0, m.err);
        QCOMPARE(readAll(merged), whole_);
        // A missing shard is named; a shard given twice repeats its cases.
        const Run missing = cli({"merge", shards[0], shards[1], "-o", "-"});
        QCOMPARE(missing.code, 2);
        QVERIFY2(missing.err.contains("is in none of the shards"), missing.err);
        const Run twice = cli(QStringList{"merge"} + shards + QStringList{shards[0], "-o", "-"});
        QCOMPARE(twice.code, 2);
        QVERIFY2(twice.err.contains("appears twice"), twice.err);
    }
    void mergeRefusesAShardOutOfCaseOrder() {
        // The merge streams, one line per shard in hand: a shard must be in case order, as
        // kinstab-cli study writes it. A shard that goes back to case 0 is named at that line.
        const QList<QByteArray> lines = whole_.trimmed().split('\n');
        const QString reversed = dir_.filePath("reversed.jsonl");
        writeBytes(reversed, lines[0] + "\n" + lines[1] + "\n" + lines[0] + "\n");
        const Run r = cli({"merge", reversed, "-o", dir_.filePath("never.jsonl")});
        QCOMPARE(r.code, 2);
        QVERIFY2(r.err.contains("reversed.jsonl:3: case 0 is not after case 1"), r.err);
        QVERIFY(!QFile::exists(dir_.filePath("never.jsonl"))); // a refused merge leaves no file
    }
    void mergeRefusesShardsOfTwoStudies() {
        // The same study with mu [0.5, 0.8]: as many cases, other rows (issue 31: merged, and
        // fragility then fitted mu 0.7 and 0.8 rows as one set).
        QTemporaryDir d;
        QByteArray other = readAll(kSpec);
        QVERIFY(other.contains("\"mu\": [0.5, 0.7]"));
        other.replace("\"mu\": [0.5, 0.7]", "\"mu\": [0.5, 0.8]");
        other.replace("../../../resources", KINSTAB_SOURCE_DIR "/resources");
        writeBytes(d.filePath("other.json"), other);
        const QString one = d.filePath("one.jsonl"), two = d.filePath("two.jsonl");
        QCOMPARE(cli({"study", "--spec", kSpec, "--shard", "1/2", "-o", one}).code, 0);
        QCOMPARE(
            cli({"study", "--spec", d.filePath("other.json"), "--shard", "2/2", "-o", two}).code,
            0);
        const Run m = cli({"merge", one, two, "-o", d.filePath("merged.jsonl")});
        QCOMPARE(m.code, 2);
        const QByteArray
            a = QJsonDocument::fromJson(readAll(one).split('\n')[0])["study"].toString().toUtf8(),
            b = QJsonDocument::fromJson(readAll(two).split('\n')[0])["study"].toString().toUtf8();
        QVERIFY(a.size() == 16 && b.size() == 16 && a != b);
        QVERIFY2(m.err.contains("two.jsonl:1: a row of another study than") &&
                     m.err.contains("one.jsonl:1's") && m.err.contains(a) && m.err.contains(b),
                 m.err.constData());
        QVERIFY(!QFile::exists(d.filePath("merged.jsonl")));
        // Concatenated into one file, fragility refuses them likewise.
        writeBytes(d.filePath("cat.jsonl"), readAll(one) + readAll(two));
        const Run f = cli({"fragility", "--results", d.filePath("cat.jsonl")});
        QCOMPARE(f.code, 2);
        QVERIFY2(f.err.contains(a) && f.err.contains(b), f.err.constData());
    }
    void mergeNamesAShardOutOfOrderAtItsLine() {
        // Shard 1/2 (cases 0, 2, 4, ...) with cases 4 and 6 swapped: case 4 is in it, later.
        QTemporaryDir d;
        const QList<QByteArray> lines = whole_.trimmed().split('\n');
        QByteArray odd, even;
        for (int i : {0, 2, 6, 4, 8, 10})
            even += lines[i] + "\n";
        for (int i : {1, 3, 5, 7, 9, 11})
            odd += lines[i] + "\n";
        writeBytes(d.filePath("even.jsonl"), even);
        writeBytes(d.filePath("odd.jsonl"), odd);
        const Run r = cli({"merge", d.filePath("even.jsonl"), d.filePath("odd.jsonl"), "-o", "-"});
        QCOMPARE(r.code, 2);
        QVERIFY2(r.err.contains("even.jsonl:4: case 4 is not after case 6"), r.err.constData());
        QVERIFY2(!r.err.contains("none of the shards"), r.err.constData());
    }
    void gnuParallelRunsTheShards() {
        if (QStandardPaths::findExecutable("parallel").isEmpty())
            QSKIP("GNU parallel is not installed (scripts/install-deps.sh installs it)");
        const QString out = dir_.filePath("parallel.jsonl");
        QProcess p;
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert("KINSTAB_CLI", KINSTAB_CLI);
        env.insert("HOME", dir_.path()); // parallel keeps its notes under $HOME/.parallel
        p.setProcessEnvironment(env);
        p.start("bash", {KINSTAB_SOURCE_DIR "/examples/parallel/run-study.sh", kSpec, out, "3"});
        QVERIFY(p.waitForFinished(300000));
        QVERIFY2(p.exitCode() == 0, p.readAllStandardError());
        QCOMPARE(readAll(out), whole_);
    }
    void slurmScriptsAreValidBash() {
        for (const char* f : {"study-array.sbatch", "submit-study.sh"}) {
            const Run r = run("bash", {"-n", QString(KINSTAB_SOURCE_DIR "/examples/slurm/") + f});
            QVERIFY2(r.code == 0, r.err);
        }
    }
    void fragilityOfTheResults() {
        const QString all = dir_.filePath("all.jsonl");
        const Run j = cli({"fragility", "--results", all, "--bootstrap", "50"});
        QVERIFY2(j.code == 0, j.err);
        const QJsonObject o = QJsonDocument::fromJson(j.out).object();
        QCOMPARE(o["measure"].toString(), QString("sa(0.5s/5%)"));
        QCOMPARE(o["sets"].toArray().size(), 4);
        const Run again = cli({"fragility", "--results", all, "--bootstrap", "50"});
        QCOMPARE(again.out, j.out); // seeded
        const Run csv =
            cli({"fragility", "--results", all, "--format", "csv", "--bootstrap", "50"});
        QVERIFY2(csv.code == 0, csv.err);
        QCOMPARE(csv.out.count('\n'), 5);
        QVERIFY(csv.out.startsWith("set,mu,tstar,"));
    }
    void badInputNamesTheField_data() {
        QTest::addColumn<QByteArray>("patch");
        QTest::addColumn<QByteArray>("named");
        QTest::newRow("mu") << QByteArray("\"parameters\": {\"mu\": [0.5, -1]}")
                            << QByteArray("parameters.mu[1] = -1");
        QTest::newRow("measure") << QByteArray("\"intensity\": {\"measure\": \"pgv\"}")
                                 << QByteArray("intensity.measure = 'pgv'");
        QTest::newRow("sa period") << QByteArray("\"intensity\": {\"measure\": \"sa\"}")
                                   << QByteArray("intensity.period_s");
        QTest::newRow("floor") << QByteArray(
                                      "\"parameters\": {\"floor_filter\": {\"dampings\": [0.02]}}")
                               << QByteArray("parameters.floor_filter.periods_s");
        QTest::newRow("search") << QByteArray("\"search\": {\"scan_step_g\": 0}")
                                << QByteArray("search");
        QTest::newRow("tstar and wall")
            << QByteArray("\"parameters\": {\"tstar\": [0.1], \"wall_width_in\": [8]}")
            << QByteArray("parameters.tstar");
    }
    void badInputNamesTheField() {
        QFETCH(QByteArray, patch);
        QFETCH(QByteArray, named);
        QTemporaryDir d;
        const Run r = cli({"study", "--spec", writeSpec(d, studyWith(patch))});
        QCOMPARE(r.code, 2);
        QVERIFY2(r.err.contains(named), r.err);
        QVERIFY(r.out.isEmpty());
    }
    void badFilesAndFlags() {
        QTemporaryDir d;
        const auto err = [&](const QStringList& args) {
            const Run r = cli(args);
            return r.code == 2 ? r.err : QByteArray("exit ") + QByteArray::number(r.code);
        };
        QVERIFY(err({"study", "--spec", writeSpec(d, "{\"format\": \"kinstab-project\"}")})
                    .contains("format = 'kinstab-project'"));
        QVERIFY(err({"study", "--spec",
                     writeSpec(d, studyWith("\"version\": 2").replace("\"version\": 1, ", ""))})
                    .contains("version = 2"));
        QVERIFY(err({"study", "--spec",
                     writeSpec(d, "{\"format\": \"kinstab-study\", \"version\": 1, \"records\": "
                                  "[{\"path\": \"nowhere\"}]}")})
                    .contains("records[0].path = 'nowhere': no such file or folder"));
        QVERIFY(err({"study", "--spec", kSpec, "--shard", "3/2"}).contains("--shard '3/2'"));
        QVERIFY(err({"study", "--spec", kSpec, "--threads", "0"}).contains("--threads '0'"));
        writeBytes(d.filePath("broken.AT2"), "not a record\n");
        QVERIFY(err({"study", "--spec",
                     writeSpec(d, "{\"format\": \"kinstab-study\", \"version\": 1, \"records\": "
                                  "[{\"path\": \"broken.AT2\"}]}")})
                    .contains("broken.AT2"));
        writeBytes(d.filePath("rows.jsonl"), "{\"case\": 0}\n");
        QVERIFY(err({"fragility", "--results", d.filePath("rows.jsonl")}).contains("rows.jsonl:1"));
        QVERIFY(err({"merge", d.filePath("rows.jsonl"), "-o", "-"}).contains("rows.jsonl:1"));
        QVERIFY(err({"merge", "-o", "-"}).contains("no shards"));
        // Rows of two studies, or a case twice, are not one study's results.
        const QByteArray rows = readAll(dir_.filePath("all.jsonl"));
        const QList<QByteArray> lines = rows.split('\n');
        writeBytes(d.filePath("twice.jsonl"), lines[0] + "\n" + lines[0] + "\n");
        QVERIFY(err({"fragility", "--results", d.filePath("twice.jsonl")})
                    .contains("twice.jsonl:2: case 0 appears twice"));
        QByteArray other = lines[1];
        other.replace("\"cases\":12", "\"cases\":13");
        writeBytes(d.filePath("mixed.jsonl"), lines[0] + "\n" + other + "\n");
        QVERIFY(err({"fragility", "--results", d.filePath("mixed.jsonl")})
                    .contains("mixed.jsonl:2: a row of another study"));
        // Sets 0, 1, 0 (cases in order): refused, not fitted as three sets (issue 30).
        qsizetype change = 1;
        while (change < lines.size() &&
               QJsonDocument::fromJson(lines[change]).object()["set"].toInt() == 0)
            ++change;
        QVERIFY(change + 1 < lines.size());
        QByteArray back = lines[0];
        back.replace("\"case\":0,", "\"case\":" + QByteArray::number(change + 1) + ",");
        writeBytes(d.filePath("split.jsonl"), lines[0] + "\n" + lines[change] + "\n" + back + "\n");
        QVERIFY(err({"fragility", "--results", d.filePath("split.jsonl")})
                    .contains("split.jsonl:3: a row of parameter set 0 after rows of another set"));
    }
    // Issue 31: one set's bootstrap is bounded (core/study/Fragility.h): 20,000 records, more
    // than a study's suite holds, take at most 500 resamples; the bounds do not depend on
    // --threads.
    void fragilityBootstrapIsBoundedAndThreaded() {
        QJsonObject row = QJsonDocument::fromJson(whole_.split('\n')[0]).object();
        QByteArray big;
        for (int i = 0; i < 20000; ++i) {
            row["case"] = i;
            row["cases"] = 20000;
            row["record"] = QString("r%1.AT2").arg(i);
            row["critical_im_g"] = 0.5 + 1e-5 * i;
            big += QJsonDocument(row).toJson(QJsonDocument::Compact) + "\n";
        }
        QTemporaryDir d;
        writeBytes(d.filePath("big.jsonl"), big);
        const Run refused = cli({"fragility", "--results", d.filePath("big.jsonl")});
        QCOMPARE(refused.code, 2);
        QVERIFY2(refused.err.contains("--bootstrap 1000: 1000 resamples x 20000 records of the set "
                                      "= 2e+07 draws, more than the limit of 1e+07: at most 500 "
                                      "resamples (or 0)"),
                 refused.err.constData());
        QVERIFY(cli({"fragility", "--results", d.filePath("big.jsonl"), "--bootstrap", "0"}).code ==
                0);
        const QString all = dir_.filePath("all.jsonl");
        const Run one =
            cli({"fragility", "--results", all, "--bootstrap", "300", "--threads", "1"});
        const Run three =
            cli({"fragility", "--results", all, "--bootstrap", "300", "--threads", "3"});
        QVERIFY2(one.code == 0 && three.code == 0, one.err + three.err);
        QCOMPARE(three.out, one.out);
        QCOMPARE(cli({"fragility", "--results", all, "--threads", "0"}).code, 2);
    }
    // --bootstrap 0: no bounds anywhere, not bounds of 0 beside the fit (issue 30).
    void fragilityWithoutBootstrapHasNoBounds() {
        const Run j =
            cli({"fragility", "--results", dir_.filePath("all.jsonl"), "--bootstrap", "0"});
        QVERIFY2(j.code == 0, j.err);
        for (const QJsonValue& s : QJsonDocument::fromJson(j.out).object()["sets"].toArray()) {
            const QJsonObject set = s.toObject();
            QVERIFY(!set.contains("median_bounds_g") && !set.contains("beta_bounds"));
            for (const QJsonValue& c : set["curve"].toArray())
                QVERIFY(c.toObject()["p_lower"].isNull() && c.toObject()["p_upper"].isNull());
        }
    }
};

QTEST_GUILESS_MAIN(TestCliStudy)
#include "tst_cli_study.moc"
