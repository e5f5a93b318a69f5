// SPDX-License-Identifier: GPL-3.0-or-later
// The Study tab (docs/studies.md): the fields make a study file kinstab-cli reads the same way,
// a run off the GUI thread fills the per-record table and the fragility chart with the same
// critical intensities as kinstab-cli study, a cancelled run shows nothing partial, a bad list
// is refused naming the field, and the export writes the rows.

#include "core/excitation/RecordMetrics.h"
#include "core/io/AtomicFile.h"
#include "core/records/RecordReader.h"
#include "ui/StudyTab.h"

#include <QChart>
#include <QChartView>
#include <QLineEdit>
#include <QProcess>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QtTest>

#include <nlohmann/json.hpp>

using namespace kinstab;
using namespace kinstab::ui;

namespace {

void smallStudy(StudyTab& tab) {
    // Two horizontal San Fernando records x mu 0.5, 0.7, as tests/data/study/small-study.json's
    // ground cases (coarse search).
    tab.setRecordsFolder(KINSTAB_SOURCE_DIR "/resources/records", "RSN68*.AT2", "*UP*");
    tab.setLists("0.5,0.7", "0.099", "");
    tab.setSearch(2.0, 0.05);
}

QString cell(const QTableWidget* t, int row, const QString& header) {
    for (int c = 0; c < t->columnCount(); ++c)
        if (t->horizontalHeaderItem(c)->text() == header) return t->item(row, c)->text();
    return "no column " + header;
}

// Issue 35: per set, the statistics of the critical intensity, recomputed here from the case
// table's own cells: a censored case ("none up to 2 g") counted, not averaged; of two collapses
// the median is their mean and the sample standard deviation |x1 - x2| / sqrt(2); of one, the
// median is it and there is no deviation.
void setTableSummarisesTheCases(const StudyTab& tab) {
    const QTableWidget* sets = tab.setTable();
    const QTableWidget* cases = tab.table();
    QCOMPARE(sets->rowCount(), 2);
    for (int s = 0; s < 2; ++s) {
        std::vector<double> x;
        int censored = 0;
        for (int r = 0; r < cases->rowCount(); ++r) {
            if (cell(cases, r, "μ") != cell(sets, s, "μ")) continue;
            bool ok = false;
            const double v = cell(cases, r, "Critical IM g").toDouble(&ok);
            if (ok)
                x.push_back(v);
            else
                ++censored;
        }
        QVERIFY(!x.empty());
        QCOMPARE(cell(sets, s, "Records"), QString::number(x.size() + censored));
        QCOMPARE(cell(sets, s, "Censored"), QString::number(censored));
        const double median = cell(sets, s, "Median g").toDouble();
        QCOMPARE_LT(std::abs(median - (x.front() + x.back()) / 2), 1e-3 * median);
        QCOMPARE(cell(sets, s, "Mean g"), cell(sets, s, "Median g"));
        if (x.size() == 2)
            QCOMPARE_LT(
                std::abs(cell(sets, s, "σ g").toDouble() - std::abs(x[0] - x[1]) / std::sqrt(2.0)),
                2e-3 * median);
        else
            QCOMPARE(cell(sets, s, "σ g"), QString("–"));
    }
}

// The record's catalogue numbers beside each case, as core computes them on the file (the
// suite gives the records unscaled; the study's measure is PGA, with no floor filter: no Sa).
void caseTableShowsTheRecordsMetrics(const StudyTab& tab) {
    const QTableWidget* cases = tab.table();
    for (int r = 0; r < cases->rowCount(); ++r) {
        const RecordMetrics m = recordMetrics(readRecord(cell(cases, r, "Record").toStdString()));
        QCOMPARE(cell(cases, r, "PGA g"), QString::number(m.pga, 'g', 3));
        QCOMPARE(cell(cases, r, "Arias m/s"), QString::number(m.arias, 'g', 3));
        QCOMPARE(cell(cases, r, "D5–95 s"), QString::number(*m.d5_95, 'g', 3));
        QCOMPARE(cell(cases, r, "Sa(T) g"), QString("–"));
    }
}

} // namespace

class TestStudyTab : public QObject {
    Q_OBJECT
private slots:
    void runFillsTableAndChartLikeTheCli() {
        StudyTab tab;
        smallStudy(tab);
        QSignalSpy done(&tab, &StudyTab::finished);
        tab.run();
        QVERIFY(done.wait(120000));
        QVERIFY2(tab.message().startsWith("4 cases"), qPrintable(tab.message()));
        QCOMPARE(tab.table()->rowCount(), 4);
        QCOMPARE(tab.fragility().size(), std::size_t(2));
        QVERIFY(!tab.chartView()->chart()->series().isEmpty());
        setTableSummarisesTheCases(tab);
        caseTableShowsTheRecordsMetrics(tab);
        // The same study through kinstab-cli: the same rows, byte for byte (the records folder
        // is absolute, so the rows name the records by absolute paths in both).
        QTemporaryDir dir;
        const QString spec = dir.filePath("gui.json");
        writeFileAtomically(spec.toStdString(), tab.studyJson());
        QProcess p;
        p.start(KINSTAB_CLI, {"study", "--spec", spec, "--threads", "1"});
        QVERIFY(p.waitForFinished(120000));
        QCOMPARE(p.exitCode(), 0);
        QCOMPARE(p.readAllStandardOutput(), QByteArray::fromStdString(tab.rows()));
        // KINSTAB_SCREENSHOT_DIR=DIR saves a picture of the tab with its results, to look at.
        if (const QString shots = qEnvironmentVariable("KINSTAB_SCREENSHOT_DIR");
            !shots.isEmpty()) {
            tab.resize(1100, 900);
            tab.show();
            QVERIFY(QTest::qWaitForWindowExposed(&tab));
            QVERIFY(tab.grab().save(shots + "/gui-study.png"));
            tab.setRecordsFolder(KINSTAB_SOURCE_DIR "/resources/records", "*.AT2", "*UP*, *DWN*");
            tab.setSearch(3.0, 0.02); // resources/examples/study-example.json
            tab.run();
            QVERIFY(done.wait(120000));
            QTest::qWait(200); // the chart lays its legend out in the event loop
            QVERIFY(tab.grab().save(shots + "/gui-study-example.png"));
        }
        const QString out = dir.filePath("rows.jsonl");
        QVERIFY(tab.exportRows(out));
        QFile f(out);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QCOMPARE(f.readAll(), QByteArray::fromStdString(tab.rows()));
        // The exported fragility is what kinstab-cli fragility makes of those rows, byte for
        // byte (the same bootstrap defaults, the same version stamp).
        const QString frag = dir.filePath("fragility.json");
        QVERIFY(tab.exportFragility(frag));
        QFile g(frag);
        QVERIFY(g.open(QIODevice::ReadOnly));
        QProcess fit;
        fit.start(KINSTAB_CLI, {"fragility", "--results", out});
        QVERIFY(fit.waitForFinished(120000));
        QCOMPARE(fit.exitCode(), 0);
        QCOMPARE(g.readAll(), fit.readAllStandardOutput());
    }
    void cancelShowsNothingPartial() {
        StudyTab tab;
        smallStudy(tab);
        tab.setLists("0.3:0.8:0.01", "0.099", ""); // 102 cases: long enough to cancel
        QSignalSpy done(&tab, &StudyTab::finished);
        tab.run();
        tab.cancel();
        QVERIFY(done.wait(120000));
        QVERIFY2(tab.message().startsWith("Cancelled"), qPrintable(tab.message()));
        QCOMPARE(tab.table()->rowCount(), 0);
        QVERIFY(tab.rows().empty());
    }
    void badListNamesTheField() {
        StudyTab tab;
        smallStudy(tab);
        tab.setLists("0.5,-1", "0.099", "");
        QSignalSpy done(&tab, &StudyTab::finished);
        tab.run();
        QVERIFY(done.wait(60000));
        QVERIFY2(tab.message().contains("parameters.mu[1] = -1"), qPrintable(tab.message()));
    }
    // The shipped block study opens with its μ and t* fields off (a block study has neither),
    // and the study the tab would run keeps the block and writes no slab list.
    void blockStudyOpensWithoutSlabFields() {
        StudyTab tab;
        QVERIFY(tab.openStudy(KINSTAB_SOURCE_DIR "/resources/examples/study-block.json"));
        for (const char* name : {"mu", "tstar"}) {
            auto* field = tab.findChild<QLineEdit*>(QString::fromLatin1(name));
            QVERIFY2(field, name);
            QVERIFY2(!field->isEnabled(), name);
        }
        const nlohmann::json j = nlohmann::json::parse(tab.studyJson());
        QVERIFY(j.contains("block"));
        QVERIFY(!j["parameters"].contains("mu"));
        QVERIFY(!j["parameters"].contains("tstar"));
    }
};

QTEST_MAIN(TestStudyTab)
#include "tst_study_tab.moc"
