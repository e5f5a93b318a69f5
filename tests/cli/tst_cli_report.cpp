// SPDX-License-Identifier: GPL-3.0-or-later
// kinstab-cli report (issue #5, docs/user-guide.md): the paper building's design report as a user
// makes it, read back with poppler's pdftotext/pdfinfo/pdfimages. Needs poppler-utils.

#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

#include "CliRun.h"

#include <cmath>

namespace {

const QString kProject =
    QStringLiteral(KINSTAB_SOURCE_DIR "/resources/examples/paper-16-story.json");

// The layout of this report for the example project: title block, verdict and signature block;
// contents; assumptions, symbols, inputs, codes, excitation, figures, γc table, slice, check,
// numerics appendix, references. A change here means the layout changed: look at the pages
// (pdftoppm) before updating it.
constexpr int kPagesA4 = 10;
constexpr int kPagesLetter = 12;

QString pdfText(const QString& pdf) {
    const Run r = run("pdftotext", {"-layout", pdf, "-"});
    return r.code == 0 ? QString::fromUtf8(r.out) : QString();
}

int pdfPages(const QString& pdf, QString* pageSize = nullptr) {
    const Run r = run("pdfinfo", {pdf});
    const QString info = QString::fromUtf8(r.out);
    if (pageSize) {
        const auto m = QRegularExpression("Page size:\\s*(.*)").match(info);
        *pageSize = m.captured(1).trimmed();
    }
    const auto m = QRegularExpression("Pages:\\s*(\\d+)").match(info);
    return m.hasMatch() ? m.captured(1).toInt() : -1;
}

} // namespace

class TestCliReport : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;
    QString a4_;

private slots:
    void initTestCase() {
        QVERIFY2(run("pdftotext", {"-v"}).code == 0,
                 "pdftotext missing: apt install poppler-utils");
        QVERIFY(dir_.isValid());
        a4_ = dir_.filePath("paper-a4.pdf");
        const Run r = cli({"report", "--project", kProject, "-o", a4_});
        QVERIFY2(r.code == 0, r.err.constData());
        const QJsonObject j = QJsonDocument::fromJson(r.out).object();
        QCOMPARE(j["output"].toString(), a4_);
        QCOMPARE(j["pages"].toInt(), pdfPages(a4_));
    }

    // Furgerson 1980 ch. V: F16/w = 0.140 (UBC 1976, F_t left out) and 0.275 (ATC 3-06);
    // docs/codes.md §1: 0.230 with F_t added to the top floor.
    void containsPaperRatios() {
        const QString text = pdfText(a4_);
        QVERIFY(text.contains("0.140"));
        QVERIFY(text.contains("0.275"));
        QVERIFY(text.contains("0.230"));
        QVERIFY(text.contains("without F_t"));
        QVERIFY(text.contains("overstress governs"));
    }

    // The building and slab inputs of resources/examples/paper-16-story.json, with units.
    void containsInputs() {
        const QString text = pdfText(a4_);
        // h_n in the project's ft, to 0.01 ft without trailing zeros (core/base/UnitSystem.h).
        for (const char* s : {"177 ft", "78.62", "dual system", "0.600", "0.0990", "moderate",
                              "SHA-256", "kinstab " KINSTAB_VERSION})
            QVERIFY2(text.contains(QString::fromUtf8(s)), s);
        QVERIFY(QRegularExpression("stories\\s+n\\s+16").match(text).hasMatch());
    }

    // The A_crit the check used, found independently by `kinstab-cli critical` with the
    // project's search settings; the paper: A = 0.95 stable, A = 1.00 collapses at f = 1 Hz.
    void containsCriticalAmplitude() {
        const Run r = cli({"critical", "--frequencies", "1", "--tolerance", "0.0001"});
        QCOMPARE(r.code, 0);
        const double aCrit =
            QJsonDocument::fromJson(r.out).object()["a_crit"].toArray()[0].toDouble();
        QVERIFY(aCrit > 0.95 && aCrit <= 1.00);
        // The verdict table's A_crit column (to 0.001 g) agrees within the search tolerance.
        const auto m =
            QRegularExpression("ATC 3-06 \\(1978\\) §4.2\\s+0.275\\s+1.000\\s+(\\d\\.\\d{3})\\s")
                .match(pdfText(a4_));
        QVERIFY(m.hasMatch());
        QCOMPARE_LE(std::abs(m.captured(1).toDouble() - aCrit), 1e-4 + 5e-4);
    }

    void vectorOnly() {
        const Run r = run("pdfimages", {"-list", a4_});
        QCOMPARE(r.code, 0);
        // Header (2 lines) and no image rows: text and line art only.
        QCOMPARE(QString::fromUtf8(r.out).trimmed().split('\n').size(), 2);
    }

    void pageCountStable() {
        QString size;
        QCOMPARE(pdfPages(a4_, &size), kPagesA4);
        QVERIFY2(size.contains("A4"), qPrintable(size));
        const QString again = dir_.filePath("again.pdf");
        QCOMPARE(cli({"report", "--project", kProject, "-o", again}).code, 0);
        QCOMPARE(pdfPages(again), kPagesA4);
    }

    void letter() {
        const QString pdf = dir_.filePath("paper-letter.pdf");
        const Run r = cli({"report", "--project", kProject, "-o", pdf, "--page", "letter"});
        QVERIFY2(r.code == 0, r.err.constData());
        QString size;
        QCOMPARE(pdfPages(pdf, &size), kPagesLetter);
        QVERIFY2(size.contains("letter"), qPrintable(size));
        QVERIFY(pdfText(pdf).contains("0.275"));
    }

    // --sections: the title block and the verdict always, then only the sections named.
    void sectionsChooseWhatIsPrinted() {
        const QString pdf = dir_.filePath("refs.pdf");
        const Run r = cli({"report", "--project", kProject, "-o", pdf, "--sections", "references"});
        QVERIFY2(r.code == 0, r.err.constData());
        const QString text = pdfText(pdf);
        QVERIFY(text.contains("Acceptance criterion"));
        QVERIFY(text.contains("References"));
        QVERIFY(!text.contains("Code inputs"));
        QVERIFY(!text.contains("Assumptions and limitations"));
        QCOMPARE_LT(pdfPages(pdf), pdfPages(a4_));
        // The help names every section key.
        const QString help = QString::fromUtf8(cli({"report", "--help"}).out);
        for (const char* key : {"assumptions", "symbols", "inputs", "codes", "excitation", "record",
                                "floors", "blocks", "surface", "check", "numerics", "references"})
            QVERIFY2(help.contains(QString::fromUtf8(key)), key);
    }

    // Run times go to the JSON, not into the report.
    void timingsInTheJson() {
        const QString pdf = dir_.filePath("timed.pdf");
        const Run r = cli({"report", "--project", kProject, "-o", pdf});
        QVERIFY2(r.code == 0, r.err.constData());
        const QJsonObject t = QJsonDocument::fromJson(r.out).object()["timings"].toObject();
        for (const char* k : {"project_sweep_s", "figure_sweeps_s", "design_check_s"})
            QVERIFY2(t[k].isDouble() && t[k].toDouble() >= 0, k);
        QVERIFY(!pdfText(pdf).contains("run time"));
    }

    void badInput_data() {
        QTest::addColumn<QString>("content"); // project file content; empty: no file
        QTest::addColumn<QStringList>("extra");
        QTest::addColumn<QString>("message");
        QTest::newRow("missing file") << QString() << QStringList() << "--project";
        QTest::newRow("truncated JSON")
            << "{\"format\": \"kinstab-project\", \"version\": 1," << QStringList() << "--project";
        QTest::newRow("negative height") << "NEGATIVE_HEIGHT" << QStringList() << "height";
        QTest::newRow("bad page size") << "EXAMPLE" << QStringList{"--page", "a5"} << "--page";
        QTest::newRow("unknown section")
            << "EXAMPLE" << QStringList{"--sections", "inputs,bogus"}
            << "--sections inputs,bogus: 'bogus' is not a report section";
        QTest::newRow("missing folder")
            << "EXAMPLE" << QStringList{"-o", "/nonexistent-folder/x.pdf"} << "-o";
    }
    void badInput() {
        QFETCH(QString, content);
        QFETCH(QStringList, extra);
        QFETCH(QString, message);
        const QString project = dir_.filePath("bad.json");
        QFile::remove(project);
        QFile example(kProject);
        QVERIFY(example.open(QIODevice::ReadOnly));
        QByteArray bytes = example.readAll();
        if (content == "NEGATIVE_HEIGHT")
            bytes.replace("\"height\": 177.0", "\"height\": -177.0");
        else if (content != "EXAMPLE")
            bytes = content.toUtf8();
        if (!content.isEmpty()) {
            QFile f(project);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write(bytes);
        }
        QStringList args{"report", "--project", project};
        if (!extra.contains("-o")) args << "-o" << dir_.filePath("bad.pdf");
        const Run r = cli(args + extra);
        QCOMPARE(r.code, 2);
        QVERIFY2(QString::fromUtf8(r.err).contains(message), r.err.constData());
        QVERIFY(!QFile::exists(dir_.filePath("bad.pdf")));
    }
};

QTEST_APPLESS_MAIN(TestCliReport)
#include "tst_cli_report.moc"
