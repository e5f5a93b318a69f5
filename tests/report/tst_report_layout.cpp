// SPDX-License-Identifier: GPL-3.0-or-later
// The report's page layout (issue #5): tables break between rows with the header repeated,
// figures never split across pages, every page says "page n of N". Read back with pdftotext.

#include "report/PageLayout.h"
#include "report/ReportWriter.h"

#include <QPdfWriter>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

using namespace kinstab::report;

namespace {

QString pdfText(const QString& pdf, int page = 0) {
    QProcess p;
    QStringList args{"-layout"};
    if (page > 0) args << "-f" << QString::number(page) << "-l" << QString::number(page);
    p.start("pdftotext", args << pdf << "-");
    p.waitForFinished(60000);
    return QString::fromUtf8(p.readAllStandardOutput());
}

} // namespace

class TestReportLayout : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

private slots:
    void tableBreaksBetweenRowsWithHeader_data() {
        QTest::addColumn<int>("paper");
        QTest::newRow("A4") << static_cast<int>(PaperSize::A4);
        QTest::newRow("Letter") << static_cast<int>(PaperSize::Letter);
    }
    void tableBreaksBetweenRowsWithHeader() {
        QFETCH(int, paper);
        ReportDocument doc;
        doc.title = "layout test";
        doc.addSection("A long table");
        Table t{{"key-column", "value-column"}, {}, {}, {}, {}};
        const int rows = 160;
        for (int r = 0; r < rows; ++r)
            t.rows.push_back({QStringLiteral("row-%1").arg(r, 3, 10, QChar('0')), "x"});
        doc.addTable(t);
        const QString pdf = dir_.filePath("table.pdf");
        const int pages = writeReportPdf(doc, pdf, static_cast<PaperSize>(paper));
        QVERIFY(pages >= 3);
        int seen = 0;
        for (int k = 1; k <= pages; ++k) {
            const QString text = pdfText(pdf, k);
            QCOMPARE(text.count("key-column"), 1); // the header repeats on every page
            QVERIFY(text.contains(QStringLiteral("page %1 of %2").arg(k).arg(pages)));
            seen += static_cast<int>(text.count("row-"));
        }
        QCOMPARE(seen, rows); // every row once: none lost or doubled at a break
    }

    void figuresNeverSplit() {
        ReportDocument doc;
        std::vector<QRectF> drawn;
        for (int k = 0; k < 7; ++k) {
            doc.addParagraph(QString("Paragraph %1. ").arg(k).repeated(30));
            doc.addFigure({[&drawn](QPainter& p, const QRectF& r) {
                               drawn.push_back(r);
                               p.drawRect(r);
                           },
                           0.62, "caption"});
        }
        QPdfWriter pdf(dir_.filePath("figures.pdf"));
        pdf.setPageSize(pageSizeOf(PaperSize::A4));
        pdf.setPageMargins(QMarginsF(0, 0, 0, 0));
        pdf.setResolution(300);
        QPainter painter(&pdf);
        ReportStyle style;
        const QRectF page(0, 0, pdf.width(), pdf.height());
        const PageLayout layout(doc, &pdf, page, style, 20.0);
        for (int k = 0; k < layout.pageCount(); ++k) {
            if (k > 0) pdf.newPage();
            layout.paintPage(painter, k);
        }
        painter.end();
        QCOMPARE(static_cast<int>(drawn.size()), 7);
        const double margin = style.px(20.0);
        for (const QRectF& r : drawn) {
            QVERIFY(r.top() >= margin - 1e-6);
            QCOMPARE_LE(r.bottom(), page.height() - margin); // inside the body: never split
        }
    }
};

QTEST_MAIN(TestReportLayout)
#include "tst_report_layout.moc"
