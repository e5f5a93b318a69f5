// SPDX-License-Identifier: GPL-3.0-or-later
// kinstab-cli report with the longest texts a project accepts (issue 31): a 200-character name,
// building name and title-block fields, with and without blanks, 50 revisions with 200-character
// descriptions and a 20,000-character description. Page 1 keeps the verdict and the signature
// block, no word runs past the right margin (pdftotext -bbox: a 200-character word used to run
// off the page and over the neighbouring table cells), and the whole revision history follows
// the report. Needs poppler-utils.

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

#include "CliRun.h"

namespace {

const QString kProject =
    QStringLiteral(KINSTAB_SOURCE_DIR "/resources/examples/paper-16-story.json");

// n characters: the word repeated with blanks between, or, with blank false, one word.
QString text(int n, const QString& word, bool blank) {
    QString s;
    while (s.size() < n)
        s += word + (blank ? QStringLiteral(" ") : QString());
    return s.left(n);
}

// The example project with every printed text at its longest.
QJsonObject longestTexts(bool blanks) {
    QFile f(kProject);
    if (!f.open(QIODevice::ReadOnly)) return {};
    QJsonObject p = QJsonDocument::fromJson(f.readAll()).object();
    p["name"] = text(200, "Longname", blanks);
    p["description"] = text(20000, "Line of a long description.\n", true);
    QJsonObject building = p["building"].toObject();
    building["name"] = text(200, "Building", blanks);
    p["building"] = building;
    QJsonObject info;
    for (const char* key : {"engineer", "registration", "firm", "client", "project_number",
                            "site_address", "prepared_by", "checked_by"})
        info[key] = text(200, "W" + QString::fromLatin1(key), blanks);
    QJsonArray revisions;
    for (int i = 0; i < 50; ++i)
        revisions.append(QJsonObject{{"id", text(12, "W" + QString::number(i), blanks)},
                                     {"date", "2026-01-01"},
                                     {"description", text(200, "Revision", blanks)}});
    info["revisions"] = revisions;
    p["info"] = info;
    return p;
}

struct Word {
    double xMax;
    QString text;
};

// The words of page `page` with their right edges, and the page width (pdftotext -bbox).
std::vector<Word> words(const QString& pdf, int page, double* pageWidth) {
    const Run r = run(
        "pdftotext", {"-bbox", "-f", QString::number(page), "-l", QString::number(page), pdf, "-"});
    const QString html = QString::fromUtf8(r.out);
    const auto w = QRegularExpression("<page width=\"([0-9.]+)\"").match(html);
    *pageWidth = w.hasMatch() ? w.captured(1).toDouble() : 0;
    std::vector<Word> out;
    const QRegularExpression re("<word xMin=\"[0-9.]+\" yMin=\"[0-9.]+\" xMax=\"([0-9.]+)\" "
                                "yMax=\"[0-9.]+\">([^<]*)</word>");
    for (auto it = re.globalMatch(html); it.hasNext();) {
        const auto m = it.next();
        out.push_back({m.captured(1).toDouble(), m.captured(2)});
    }
    return out;
}

QString flatText(const QString& pdf, int first, int last) {
    const Run r = run("pdftotext", {"-f", QString::number(first), "-l", QString::number(last),
                                    "-layout", pdf, "-"});
    return QString::fromUtf8(r.out).simplified();
}

} // namespace

class TestCliReportText : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

private slots:
    void initTestCase() {
        QVERIFY2(run("pdftotext", {"-v"}).code == 0,
                 "pdftotext missing: apt install poppler-utils");
        QVERIFY(dir_.isValid());
    }

    void pageOneHoldsTheLongestTexts_data() {
        QTest::addColumn<bool>("blanks");
        QTest::addColumn<QString>("paper");
        QTest::newRow("words, A4") << true << "a4";
        QTest::newRow("one word each, A4") << false << "a4";
        QTest::newRow("words, letter") << true << "letter";
        QTest::newRow("one word each, letter") << false << "letter";
    }
    void pageOneHoldsTheLongestTexts() {
        QFETCH(bool, blanks);
        QFETCH(QString, paper);
        const QString project = dir_.filePath("longest.json");
        QFile f(project);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(QJsonDocument(longestTexts(blanks)).toJson());
        f.close();
        const QString pdf = dir_.filePath("longest.pdf");
        const Run r = cli({"report", "--project", project, "--page", paper, "-o", pdf});
        QVERIFY2(r.code == 0, r.err.constData());
        const int pages = QJsonDocument::fromJson(r.out).object()["pages"].toInt();
        const QString page1 = flatText(pdf, 1, 1);
        QVERIFY2(page1.contains("Governing check: sine."), qPrintable(page1));
        QCOMPARE(page1.count("signature"), 3);
        QVERIFY(page1.contains("seal"));
        QVERIFY(page1.contains("Reg. no. Wregistration"));
        QVERIFY(page1.contains("47 earlier revisions"));
        // Every word ends left of the right margin (20 mm, 56.7 pt), beyond the page's 0.5 pt.
        double width = 0;
        const std::vector<Word> ws = words(pdf, 1, &width);
        QVERIFY(width > 500 && ws.size() > 100);
        for (const Word& w : ws)
            QVERIFY2(w.xMax <= width - 56.7 + 0.5, qPrintable(w.text.left(40)));
        // The whole history, on the last pages: all 50 marks, with the first.
        const QString end = flatText(pdf, std::max(2, pages - 3), pages);
        QVERIFY(end.contains("Revision history"));
        QCOMPARE(end.count("2026-01-01"), 50);
    }
};

QTEST_APPLESS_MAIN(TestCliReportText)
#include "tst_cli_report_text.moc"
