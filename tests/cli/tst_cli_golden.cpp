// SPDX-License-Identifier: GPL-3.0-or-later
// kinstab-cli's JSON outputs on a fixed set of commands (the twelve in tests/data/golden/: surface,
// critical, codes, check, simulate and floors, 1-DOF and planar), every number bit-identical to
// its golden file. Before comparing, both sides lose the keys that change from run to run
// (version, wall times, rates, thread counts) and the checkout's folder in record paths, and their
// keys are sorted; numbers are compared as the bits of the doubles they parse to, so "1" and "1.0"
// agree and 0.7999999999999999 and 0.8 do not. planarCheckIsThePlanarCritical ties the planar
// check's A_crit to `critical --model planar`. When a golden is rewritten on purpose, CHANGELOG.md
// says which, why and by how much its numbers moved.

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
