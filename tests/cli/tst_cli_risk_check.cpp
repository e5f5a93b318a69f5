// SPDX-License-Identifier: GPL-3.0-or-later
// The risk checks through the front ends (docs/assessment.md, "risk"): `kinstab-cli check
// --project` on the risk example prints risk.set0 and risk.set1 in assessment.checks, each with
// the demand `kinstab-cli risk --hazard H --results R --set K` prints as lambda_c for the same
// files (the same engine's CLI path), the target rate as capacity and target / lambda_C as
// margin; the report's page 1 lists them with their verdicts and its Risk section prints
// lambda_C at its precision (3 significant digits), read back with pdftotext; the table format
// prints the rate, not "0.000".

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

#include "CliRun.h"

#include <cmath>

namespace {

const QString kExamples = QStringLiteral(KINSTAB_SOURCE_DIR "/resources/examples/");
const QString kProject = kExamples + "paper-16-story-risk.json";

QString squeeze(QString s) {
    return s.replace(QRegularExpression("\\s+"), QStringLiteral(" "));
}

QJsonArray riskChecks(const QJsonObject& assessment) {
    QJsonArray out;
    for (const QJsonValue& v : assessment["checks"].toArray())
        if (v.toObject()["basis"].toString() == "risk") out.append(v);
    return out;
}

} // namespace

class TestCliRiskCheck : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;
    QJsonObject assessment_;

private slots:
    void initTestCase() {
        const Run check = cli({"check", "--project", kProject, "--format", "json"});
        QVERIFY2(check.code == 0, check.err.constData());
        assessment_ = QJsonDocument::fromJson(check.out).object()["assessment"].toObject();
    }

    void checkPrintsTheRiskChecks() {
        const QJsonArray checks = riskChecks(assessment_);
        QCOMPARE(checks.size(), 2); // the study's two sets (mu = 0.4, 0.6)
        for (int k = 0; k < checks.size(); ++k) {
            const QJsonObject c = checks[k].toObject();
            QCOMPARE(c["id"].toString(), QStringLiteral("risk.set%1").arg(k));
            QCOMPARE(c["unit"].toString(), QStringLiteral("1/yr"));
            QCOMPARE(c["intensity"].toString(), QStringLiteral("annual rate"));
            QCOMPARE(c["level"].toString(), QStringLiteral("collapse"));
            const Run risk =
                cli({"risk", "--hazard", kExamples + "hazard-second-order.csv", "--results",
                     kExamples + "study-example.jsonl", "--set", QString::number(k)});
            QVERIFY2(risk.code == 0, risk.err.constData());
            const double lambda = QJsonDocument::fromJson(risk.out).object()["lambda_c"].toDouble();
            QCOMPARE(c["demand"].toDouble(), lambda);
            // -ln(0.99) / 50, the code's 1 % in 50 years (core/risk/RiskTargets.h).
            const double target = -std::log(0.99) / 50;
            QCOMPARE_LT(std::abs(c["capacity"].toDouble() / target - 1), 1e-14);
            QCOMPARE_LT(std::abs(c["margin"].toDouble() / (target / lambda) - 1), 1e-14);
            QCOMPARE(c["holds"].toBool(), lambda < target);
        }
    }

    void tablePrintsTheRate() {
        const Run table = cli({"check", "--project", kProject, "--format", "table"});
        QVERIFY2(table.code == 0, table.err.constData());
        const QString text = QString::fromUtf8(table.out);
        const QJsonObject c = riskChecks(assessment_)[0].toObject();
        const QString demand = QString::number(c["demand"].toDouble(), 'e', 2);
        QVERIFY2(text.contains(
                     QRegularExpression("risk\\.set0\\s+" + QRegularExpression::escape(demand))),
                 qPrintable(text));
    }

    void reportPageOneAndRiskSection() {
        const QString pdf = dir_.filePath("risk.pdf");
        const Run report = cli({"report", "--project", kProject, "-o", pdf});
        QVERIFY2(report.code == 0, report.err.constData());
        const Run one = run("pdftotext", {"-f", "1", "-l", "2", pdf, "-"});
        const QString page = squeeze(QString::fromUtf8(one.out));
        const Run all = run("pdftotext", {pdf, "-"});
        const QString text = squeeze(QString::fromUtf8(all.out));
        QVERIFY(text.contains("Risk: annual rate of the slab falling"));
        for (const QJsonValue& v : riskChecks(assessment_)) {
            const QJsonObject c = v.toObject();
            const QString id = c["id"].toString();
            const QString demand = QString::number(c["demand"].toDouble(), 'e', 2);
            QVERIFY2(page.contains(id + " " + demand + " 1/yr"), qPrintable(id + "\n" + page));
            QVERIFY2(page.contains(c["verdict"].toString()), qPrintable(c["verdict"].toString()));
            QVERIFY2(text.contains(demand), qPrintable(demand));
        }
    }
};

QTEST_GUILESS_MAIN(TestCliRiskCheck)
#include "tst_cli_risk_check.moc"
