// SPDX-License-Identifier: GPL-3.0-or-later
// Chart exports (File → Export chart…) go through core's atomic writer (issue 14): a complete
// SVG or PNG replaces the old file whole; a failed write names the file and the reason and
// leaves the old file alone.

#include <QChart>
#include <QChartView>
#include <QFile>
#include <QLineSeries>
#include <QTemporaryDir>
#include <QtTest>

#include "ui/ChartExport.h"

namespace {

QByteArray readAll(const QString& path) {
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

} // namespace

class TestChartExport : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;
    std::unique_ptr<QChartView> view_;

private slots:
    void initTestCase() {
        QVERIFY(dir_.isValid());
        auto* series = new QLineSeries;
        series->append({{0, 0}, {1, 2}, {2, 1}});
        auto* chart = new QChart;
        chart->addSeries(series);
        chart->setTitle("export test");
        view_ = std::make_unique<QChartView>(chart);
        view_->resize(400, 300);
    }

    void svgReplacesOldFile() {
        const QString path = dir_.filePath("chart.svg");
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("old");
        f.close();
        QCOMPARE(kinstab::ui::exportChart(view_.get(), path), QString());
        const QByteArray svg = readAll(path);
        QVERIFY(svg.contains("<svg"));
        QVERIFY(svg.trimmed().endsWith("</svg>"));
        QVERIFY(svg.contains("export test"));
    }

    void pngIsAPng() {
        const QString path = dir_.filePath("chart.png");
        QCOMPARE(kinstab::ui::exportChart(view_.get(), path), QString());
        QVERIFY(readAll(path).startsWith("\x89PNG\r\n"));
    }

    void failedWriteNamesFileAndReason() {
        const QString missing = dir_.filePath("no/such/folder/chart.svg");
        const QString e = kinstab::ui::exportChart(view_.get(), missing);
        QVERIFY2(e.contains(missing) && e.contains("No such file or directory"), qPrintable(e));
        if (QFile::exists("/dev/full")) {
            // A .svg link to /dev/full: not a regular file, so written straight through, and full.
            const QString full = dir_.filePath("full.svg");
            QVERIFY(QFile::link("/dev/full", full));
            const QString e2 = kinstab::ui::exportChart(view_.get(), full);
            QVERIFY2(e2.contains("No space left on device"), qPrintable(e2));
        }
    }
};

QTEST_MAIN(TestChartExport)
#include "tst_chart_export.moc"
