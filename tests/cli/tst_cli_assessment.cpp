// SPDX-License-Identifier: GPL-3.0-or-later
// One assessment, every front end: on every example project `kinstab-cli check` prints the
// assessment (checks, governing) and the report's page 1 lists the same checks with the same
// verdicts and the same governing check and margin (read back with pdftotext). Page 1 says
// nothing the project contradicts: the planar example has no vertical motion and rests on
// ch. VI; no sentence points at a numbered section. The table format names the governing check.

#include <QDir>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

#include "CliRun.h"

namespace {

const QString kExamples = QStringLiteral(KINSTAB_SOURCE_DIR "/resources/examples/");

// The example projects `check` accepts (the study example's report runs its study: see
// tst_cli_report_study).
const QStringList kProjects = {"paper-16-story.json", "paper-16-story-record.json",
                               "paper-16-story-floors.json", "paper-planar.json"};

// Page 1 as text, in reading order; the summary ends where the contents begin.
QString pageOne(const QString& pdf) {
    const Run r = run("pdftotext", {"-f", "1", "-l", "2", pdf, "-"});
    const QString text = QString::fromUtf8(r.out);
    const int contents = text.indexOf(QStringLiteral("\nContents"));
    return contents > 0 ? text.left(contents) : text;
}

// One line of words, with the ligatures of the PDF's fonts spelled out ("ﬂoors" is "floors").
QString squeeze(QString s) {
    const std::pair<const char*, const char*> ligatures[] = {
        {"ﬃ", "ffi"}, {"ﬄ", "ffl"}, {"ﬀ", "ff"}, {"ﬁ", "fi"}, {"ﬂ", "fl"}};
    for (const auto& [from, to] : ligatures)
        s.replace(QString::fromUtf8(from), QString::fromUtf8(to));
    return s.replace(QRegularExpression("\\s+"), QStringLiteral(" "));
}

} // namespace

class TestCliAssessment : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

private slots:
    void checkAndPageOneAgree_data();
    void checkAndPageOneAgree();
    void planarPageOneSaysWhatRan();
    void tableNamesTheGoverningCheck();
};

void TestCliAssessment::checkAndPageOneAgree_data() {
    QTest::addColumn<QString>("project");
    for (const QString& p : kProjects)
        QTest::newRow(qPrintable(p)) << p;
}

void TestCliAssessment::checkAndPageOneAgree() {
    QFETCH(QString, project);
    const Run check = cli({"check", "--project", kExamples + project, "--format", "json"});
    QVERIFY2(check.code == 0, check.err.constData());
    const QJsonObject a = QJsonDocument::fromJson(check.out).object()["assessment"].toObject();
    const QJsonArray checks = a["checks"].toArray();
    QVERIFY(!checks.isEmpty());
    const QString pdf = dir_.filePath(project + ".pdf");
    const Run report = cli({"report", "--project", kExamples + project, "-o", pdf});
    QVERIFY2(report.code == 0, report.err.constData());
    const QString page = squeeze(pageOne(pdf));
    for (const QJsonValue& v : checks) {
        const QJsonObject c = v.toObject();
        const QString id = c["id"].toString();
        // The row: id, demand, capacity ("none"), margin ("> 2.5"), verdict.
        const QRegularExpression row(QRegularExpression::escape(id) + "\\s[\\s0-9.>none]*?" +
                                     QRegularExpression::escape(c["verdict"].toString()));
        QVERIFY2(row.match(page).hasMatch(),
                 qPrintable(id + " / " + c["verdict"].toString() + " not on page 1:\n" + page));
    }
    const QJsonObject g = a["governing"].toObject();
    const QString margin = g["margin"].isNull()
                               ? "> " + QString::number(g["margin_at_least"].toDouble(), 'f', 2)
                               : QString::number(g["margin"].toDouble(), 'f', 2);
    const QString governing = "Governing check: " + g["id"].toString();
    QVERIFY2(page.contains(governing), qPrintable(governing + " not on page 1"));
    QVERIFY2(page.contains("margin " + margin), qPrintable("margin " + margin));
    QVERIFY(!page.contains(QStringLiteral("section 5")));
}

void TestCliAssessment::planarPageOneSaysWhatRan() {
    const QString pdf = dir_.filePath("planar-page1.pdf");
    const Run report = cli({"report", "--project", kExamples + "paper-planar.json", "-o", pdf});
    QVERIFY2(report.code == 0, report.err.constData());
    const QString page = squeeze(pageOne(pdf));
    QVERIFY2(!page.contains(QStringLiteral("with vertical motion")), qPrintable(page));
    QVERIFY(page.contains(QStringLiteral("no vertical motion")));
    QVERIFY(page.contains(QStringLiteral("ch. VI")));
    QVERIFY(!page.contains(QStringLiteral("ch. IV)")));
    QVERIFY(page.contains(QStringLiteral("planar.ubc1976")));
}

void TestCliAssessment::tableNamesTheGoverningCheck() {
    const Run table =
        cli({"check", "--project", kExamples + "paper-16-story-floors.json", "--format", "table"});
    QVERIFY2(table.code == 0, table.err.constData());
    const Run json = cli({"check", "--project", kExamples + "paper-16-story-floors.json"});
    const QString id = QJsonDocument::fromJson(json.out)
                           .object()["assessment"]
                           .toObject()["governing"]
                           .toObject()["id"]
                           .toString();
    QVERIFY(!id.isEmpty());
    QVERIFY(QString::fromUtf8(table.out).contains("governing: " + id));
    QVERIFY(QString::fromUtf8(table.out).contains("floors.asce7_22.mce_r"));
}

QTEST_GUILESS_MAIN(TestCliAssessment)
#include "tst_cli_assessment.moc"
