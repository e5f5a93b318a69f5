// SPDX-License-Identifier: GPL-3.0-or-later
// File → Export report in the GUI (issue #5): the window's project goes through the same
// worker analysis and writer as `kinstab-cli report`; read back with poppler's pdftotext.
// Independent check: A_crit at the building's f = 1/T found here with core's search on the
// window's slab case (the paper: A = 0.95 stable, A = 1.00 collapses at 1 Hz).

#include "core/sweep/CriticalAmplitude.h"
#include "core/sweep/Sweep.h"
#include "ui/MainWindow.h"
#include "ui/ReportExport.h"

#include <QApplication>
#include <QMessageBox>
#include <QProcess>
#include <QRegularExpression>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTimer>
#include <QtTest>

using namespace kinstab;
using namespace kinstab::ui;

namespace {

QString pdfText(const QString& pdf) {
    QProcess p;
    p.start("pdftotext", {"-layout", pdf, "-"});
    p.waitForFinished(60000);
    return QString::fromUtf8(p.readAllStandardOutput());
}

// Runs one export to its end (the window's event loop keeps running meanwhile).
QString exportAndWait(QWidget* w, const Project& p, const QString& out) {
    QSignalSpy done(ui::exportReportTo(w, p, QString(), out), &ui::ReportExport::done);
    if (!done.wait(300000)) return QStringLiteral("(no result in 300 s)");
    return done.at(0).at(0).toString();
}

} // namespace

class TestReportExport : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QSettings().clear();
    }

    void exportsTheWindowsProject() {
        MainWindow w; // starts with the paper's 16-story example
        const Project p = w.project();
        const QString pdf = dir_.filePath("gui-report.pdf");
        QCOMPARE(exportAndWait(&w, p, pdf), pdf);
        const QString text = pdfText(pdf);
        QVERIFY(text.contains("Kinetic stability design report"));
        // Never saved: the title block hashes the project JSON as used and says so.
        QVERIFY(text.contains("unsaved project"));
        QVERIFY(text.contains(
            QString::fromStdString(p.name))); // (the building's name has an "ffi" ligature)

        const double f = 1.0 / p.building.period.value_or(1.0);
        const CriticalResult c =
            criticalAmplitude(slab1DPoint(p.slab), f, p.slab.slab.mu, p.critical);
        QVERIFY(c.amplitude && *c.amplitude > 0.95 && *c.amplitude <= 1.00);
        const auto m =
            QRegularExpression("ATC 3-06 \\(1978\\) §4.2\\s+0.275\\s+1.000\\s+(\\d\\.\\d{3})\\s")
                .match(text);
        QVERIFY2(m.hasMatch(), qPrintable(text.left(3000)));
        // Printed to 0.001 g (report/ReportSections.h, accelG).
        QCOMPARE_LE(std::abs(m.captured(1).toDouble() - *c.amplitude), p.critical.tolerance + 5e-4);
    }

    void unwritablePathFailsWithoutCrash() {
        MainWindow w;
        // The failure's message box would block: close it as soon as it opens.
        QTimer closer;
        QObject::connect(&closer, &QTimer::timeout, [] {
            for (QWidget* top : QApplication::topLevelWidgets())
                if (auto* box = qobject_cast<QMessageBox*>(top)) box->close();
        });
        closer.start(50);
        QCOMPARE(exportAndWait(&w, w.project(), dir_.filePath("missing-dir/report.pdf")),
                 QString());
    }
};

QTEST_MAIN(TestReportExport)
#include "tst_report_export.moc"
