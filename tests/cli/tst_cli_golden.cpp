// SPDX-License-Identifier: GPL-3.0-or-later
// kinstab-cli's JSON outputs on a fixed set of commands, every number bit-identical to a golden
// file (issue 15: moving the analysis into one core entry point must not change a single bit).
// The goldens in tests/data/golden/ were written by kinstab-cli as it was before the #15
// refactor (commit c5b59cc), run from the repository root, with the keys that change from run
// to run (version, wall times, rates, thread counts) removed, the keys sorted, and the checkout's
// folder cut from the record paths that projects resolve. The same is done here before
// comparing; numbers are compared as the bits of the doubles they parse to, so "1" and "1.0"
// agree and 0.7999999999999999 and 0.8 do not.
// One golden is an intended change: 08-check-planar.json. Before #15 `check` refused a planar
// project (exit 2, "the design check uses the slab1d model"); through the analysis entry point
// it runs the planar model's check, and that golden was written by the CLI after the change;
// planarCheckIsThePlanarCritical checks its A_crit against `critical --model planar` there.
// The planar goldens (04, 08, 10, 11) were rewritten once more by the faster planar solver of
// issue 22: τc and γc moved by at most 1e-11 (within the solver's tolerance), max |dx| is now
// the interpolated peak inside a step rather than the largest step end (0.76601 → 0.76691 in
// 10), and A_crit at 1.5 Hz in 04 fell from 0.839468 to 0.839241 g: between them the slab
// passes the wall's edge inside one integration step and comes back (max |dx| 1.00005 by the
// interpolant), a collapse the old end-of-step check missed; the step is now retaken to end at
// that peak, where the integrated state itself is beyond the edge.
// 10 and 11 were rewritten again when slow slips went to the implicit Radau IIA step (issue
// 22): γc moved by at most 1.3e-11 relative, max |dx| in 10 by 4e-10 (the interpolated peak
// inside a step depends on where the steps fall), the work counters fell.
// 10 and 11 were rewritten a third time when the planar excitation went to local Taylor series
// (core/slab/SinePairSeries.h, within 2 units of the phase's rounding of the closed forms) and
// DOP853's step factor to square roots instead of pow: γc and τc moved by at most 3.4e-11
// relative, max |dx| in 10 by 2.7e-10 and its residual dx by 7.9e-10.
// 10 and 11 were rewritten a fourth time when the implicit step went to five-stage Radau IIA
// (order 9) with predictive step control: γc and τc moved by at most 5.6e-12 relative, the
// residual dx in 10 by 1.8e-9 (now 7e-12 from the value at rtol 1e-13, was 2.6e-10) and its
// max |dx|, a cubic interpolant's peak inside an explicit step, by 5.1e-7 (now 3.4e-7 from the
// value at rtol 1e-13, was 7.5e-7); the steps fell from 559 to 362.
// Issue 30 added keys and changed none: 06, 07 and 08 gained "assessment" (every value that was
// there before is bit-identical); 12 gained "checks" (the assessment's floor checks) and lost
// "verdicts", "enveloped_sine_a_crit_g" and "enveloped_sine_verdicts", the floor verdicts that
// contradicted the assessment.
// Issue 34 (the exact solver's evaluations per event, 8.42 -> 6.18) rewrote 01, 02 and 09: the
// stop searches take the slopes at their ends from evaluations already made and the |a| = mu
// crossings start nearer their roots, so Newton starts elsewhere and ends a few ulps apart on
// some roots: 43 of the 120 tau_c/gamma_c values in 01 and 170 of 2178 in 02 moved by at most
// 3.9e-15 relative (no outcome changed); in 09 only the work counter fell (114 -> 111).

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QtTest>

#include "CliRun.h"

#include <bit>
#include <cstdint>

namespace {

struct Golden {
    const char* file; // in tests/data/golden/
    QStringList args;
};

QList<Golden> goldens() {
    return {
        {"01-surface-paper-grid.json",
         {"surface", "--amplitudes", "0.70:1.15:0.05", "--frequencies", "0.5:1.125:0.125"}},
        {"02-surface-33x33-fast.json",
         {"surface", "--amplitudes", "0.2:1.8:0.05", "--frequencies", "0.25:4.25:0.125",
          "--envelope", "fast"}},
        {"03-critical-slab1d.json", {"critical", "--frequencies", "0.5:2:0.25"}},
        {"04-critical-planar.json",
         {"critical", "--frequencies", "0.5:2:0.5", "--model", "planar", "--fy", "1"}},
        {"05-codes-paper.json", {"codes", "--project", "resources/examples/paper-16-story.json"}},
        {"06-check-paper.json", {"check", "--project", "resources/examples/paper-16-story.json"}},
        {"07-check-record.json",
         {"check", "--project", "resources/examples/paper-16-story-record.json"}},
        {"08-check-planar.json", {"check", "--project", "resources/examples/paper-planar.json"}},
        {"09-simulate-record-critical.json",
         {"simulate", "--record", "resources/records/RSN77_SFERN_PUL164.AT2", "--floor-period", "1",
          "--critical"}},
        {"10-simulate-planar.json",
         {"simulate", "--model", "planar", "--amplitude", "0.9", "--frequency", "2", "--fy",
          "0.2"}},
        {"11-surface-planar.json",
         {"surface", "--model", "planar", "--fy", "1", "--amplitudes", "0.7:1.1:0.1",
          "--frequencies", "0.5:1.5:0.25"}},
        {"12-floors-paper.json",
         {"floors", "--project", "resources/examples/paper-16-story-floors.json"}},
    };
}

// Keys whose values differ between two runs of the same command.
bool volatileKey(const QString& key) {
    static const QRegularExpression re("kinstab_version|seconds|wall|elapsed|per_second|threads");
    return re.match(key).hasMatch();
}

QJsonValue stripped(const QJsonValue& v) {
    if (v.isObject()) {
        QJsonObject o;
        const QJsonObject in = v.toObject();
        for (auto it = in.begin(); it != in.end(); ++it)
            if (!volatileKey(it.key())) o.insert(it.key(), stripped(it.value()));
        return o;
    }
    if (v.isArray()) {
        QJsonArray a;
        for (const QJsonValue& e : v.toArray())
            a.append(stripped(e));
        return a;
    }
    if (v.isString()) { // a path resolved against the project's folder, in this checkout
        QString t = v.toString();
        if (t.startsWith(QStringLiteral(KINSTAB_SOURCE_DIR "/")))
            t.remove(0, QStringLiteral(KINSTAB_SOURCE_DIR "/").size());
        return t;
    }
    return v;
}

// The first difference between two JSON values ("" when equal), with its path.
QString difference(const QJsonValue& got, const QJsonValue& want, const QString& path) {
    if (got.type() != want.type()) return path + ": type differs";
    if (got.isDouble()) {
        const auto a = std::bit_cast<std::uint64_t>(got.toDouble());
        const auto b = std::bit_cast<std::uint64_t>(want.toDouble());
        return a == b ? QString()
                      : path + QString(": %1 != golden %2")
                                   .arg(got.toDouble(), 0, 'g', 17)
                                   .arg(want.toDouble(), 0, 'g', 17);
    }
    if (got.isArray()) {
        const QJsonArray a = got.toArray(), b = want.toArray();
        if (a.size() != b.size()) return path + ": array length differs";
        for (qsizetype i = 0; i < a.size(); ++i)
            if (QString d = difference(a[i], b[i], path + QString("[%1]").arg(i)); !d.isEmpty())
                return d;
        return {};
    }
    if (got.isObject()) {
        const QJsonObject a = got.toObject(), b = want.toObject();
        if (a.keys() != b.keys()) return path + ": keys differ";
        for (const QString& k : a.keys())
            if (QString d = difference(a[k], b[k], path + "." + k); !d.isEmpty()) return d;
        return {};
    }
    return got == want ? QString() : path + ": value differs";
}

// kinstab-cli run from the repository root: the commands name files relative to it.
Run cliAtRoot(const QStringList& args) {
    QProcess p;
    p.setWorkingDirectory(KINSTAB_SOURCE_DIR);
    p.start(KINSTAB_CLI, args);
    if (!p.waitForFinished(600000)) p.kill();
    return {p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1, p.readAllStandardOutput(),
            p.readAllStandardError()};
}

QJsonDocument parsed(const QByteArray& text, const QString& what) {
    QJsonParseError e;
    const QJsonDocument d = QJsonDocument::fromJson(text, &e);
    if (e.error != QJsonParseError::NoError)
        qWarning().noquote() << what << "is not JSON:" << e.errorString();
    return d;
}

} // namespace

class TestCliGolden : public QObject {
    Q_OBJECT
private slots:
    void outputs_data() {
        QTest::addColumn<QString>("file");
        QTest::addColumn<QStringList>("args");
        for (const Golden& g : goldens())
            QTest::newRow(g.file) << QString(g.file) << g.args;
    }

    void outputs() {
        QFETCH(QString, file);
        QFETCH(QStringList, args);
        const Run r = cliAtRoot(args);
        QVERIFY2(r.code == 0, r.err.constData());
        QFile f(QStringLiteral(KINSTAB_TEST_DATA "/golden/") + file);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QJsonDocument got = parsed(r.out, "the output");
        const QJsonDocument want = parsed(f.readAll(), file);
        QVERIFY(got.isObject() && want.isObject());
        const QString d = difference(stripped(got.object()), stripped(want.object()), "$");
        QVERIFY2(d.isEmpty(), qPrintable(d));
    }

    // The planar project's check (period 1 s, f_y = 0.2 Hz, A_y/A_x = 0.9, theta = 20, gravity
    // only: resources/examples/paper-planar.json) finds the same A_crit as the planar critical
    // command at f = 1 Hz with those inputs: one search, reached two ways.
    void planarCheckIsThePlanarCritical() {
        const Run check = cliAtRoot({"check", "--project", "resources/examples/paper-planar.json"});
        const Run crit = cliAtRoot({"critical", "--model", "planar", "--frequencies", "1", "--fy",
                                    "0.2", "--ay-ratio", "0.9", "--theta", "20"});
        QCOMPARE(check.code, 0);
        QCOMPARE(crit.code, 0);
        const QJsonObject checkJson = QJsonDocument::fromJson(check.out).object();
        const double a = QJsonDocument::fromJson(crit.out)["a_crit"][0].toDouble();
        QVERIFY(a > 0);
        QCOMPARE(checkJson["codes"].toObject().size(), 4);
        for (const QString& code : checkJson["codes"].toObject().keys())
            QVERIFY(checkJson["codes"][code]["a_crit"].toDouble() == a); // the same bits
    }
};

QTEST_GUILESS_MAIN(TestCliGolden)
#include "tst_cli_golden.moc"
