// SPDX-License-Identifier: GPL-3.0-or-later
// The project's study in the window (docs/studies.md): opening a project shows its study in the
// Study tab, with its results read back (named by the project, or found beside it) and never
// results of another study (other inputs, or only another search: the rows' fingerprint);
// opening a project without one clears the tab; "Use in project" puts
// the study and the results of its run into the project, marked unsaved, and saving and
// reopening shows them again; editing the fields after a run marks the results stale.
// The numbers compared are those of a real run of `kinstab-cli study` on two shipped records and
// of core's fragility fit on those rows.

#include "core/io/AtomicFile.h"
#include "core/io/StudyResults.h"
#include "core/io/StudySpecJson.h"
#include "core/study/Fragility.h"
#include "core/study/StudyRecords.h"
#include "core/study/StudyRowsMatch.h"
#include "ui/InputHistory.h"
#include "ui/MainWindow.h"
#include "ui/StudyTab.h"

#include <QChart>
#include <QChartView>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QProcess>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTabWidget>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QtTest>

using namespace kinstab;
using namespace kinstab::ui;

namespace {

const QString kNoStudy =
    QStringLiteral(KINSTAB_SOURCE_DIR "/resources/examples/paper-16-story.json");

// The six horizontal AT2 records shipped x mu 0.4, 0.6 (12 cases, coarse search: every record
// collapses the slab below 3 g, so both sets have a fit); `mu` replaces the list for a study of
// other cases.
QByteArray tinyStudy(const char* mu = "[0.4, 0.6]") {
    return QByteArray("{\"format\": \"kinstab-study\", \"version\": 1, \"name\": \"tiny\", "
                      "\"records\": [{\"path\": \"" KINSTAB_SOURCE_DIR "/resources/records\", "
                      "\"include\": [\"*.AT2\"], \"exclude\": [\"*UP*\", \"*DWN*\"]}], "
                      "\"intensity\": {\"measure\": \"pga\"}, \"parameters\": {\"mu\": ") +
           mu + ", \"tstar\": [0.099]}, \"search\": {\"max_g\": 3, \"scan_step_g\": 0.05}}\n";
}

void write(const QString& path, const QByteArray& text) {
    writeFileAtomically(path.toStdString(), text.toStdString());
}

QByteArray readAll(const QString& path) {
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

// The paper's example project with `study` (absent when empty), written to `path`.
// Runs kinstab-cli study on spec into rows: "" when it succeeds, else what it said.
QString runStudy(const QString& spec, const QString& rows) {
    QProcess p;
    p.start(KINSTAB_CLI, {"study", "--spec", spec, "--threads", "1", "-o", rows});
    if (!p.waitForFinished(300000)) return QStringLiteral("kinstab-cli study did not finish");
    return p.exitCode() == 0 ? QString() : QString::fromUtf8(p.readAllStandardError());
}

QString projectWith(const QString& path, const QJsonObject& study) {
    QJsonObject p = QJsonDocument::fromJson(readAll(kNoStudy)).object();
    if (!study.isEmpty()) p["study"] = study;
    write(path, QJsonDocument(p).toJson());
    return path;
}

// The critical intensities as the tab's table shows them.
QStringList criticalColumn(const QTableWidget* t) {
    QStringList out;
    for (int i = 0; i < t->rowCount(); ++i)
        out << t->item(i, 4)->text();
    return out;
}

QStringList criticalColumn(const std::vector<StudyRow>& rows) {
    QStringList out;
    for (const StudyRow& r : rows)
        out << (r.criticalIntensity ? QString::number(*r.criticalIntensity, 'g', 4)
                                    : QStringLiteral("none up to %1 g")
                                          .arg(QString::number(r.limitIntensity, 'g', 4)));
    return out;
}

bool isCleared(const StudyTab* tab) {
    return tab->studyFile().isEmpty() && tab->table()->rowCount() == 0 &&
           tab->fragility().empty() && tab->rows().empty() &&
           tab->chartView()->chart()->series().isEmpty();
}

} // namespace

class TestStudyProject : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;
    QString spec_, rows_;
    std::vector<StudyRow> cliRows_;

    // Opens `project` and waits until the tab has read its results, if it reads any.
    // With KINSTAB_SCREENSHOT_DIR set, the window at 1920x1080 with the Study tab in front.
    void screenshot(MainWindow& w, const QString& name) {
        const QString shots = qEnvironmentVariable("KINSTAB_SCREENSHOT_DIR");
        if (shots.isEmpty()) return;
        for (QTabWidget* tabs : w.findChildren<QTabWidget*>())
            for (int i = 0; i < tabs->count(); ++i)
                if (tabs->tabText(i) == QStringLiteral("Study")) tabs->setCurrentIndex(i);
        w.resize(1920, 1080);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QTest::qWait(300); // the chart lays its legend out in the event loop
        QVERIFY(w.grab().save(shots + "/" + name));
    }

    bool open(MainWindow& w, const QString& project, bool readsResults) {
        QSignalSpy done(w.studyTab(), &StudyTab::finished);
        if (!w.openProject(project, true)) return false;
        return !readsResults || done.wait(60000);
    }

private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QVERIFY(dir_.isValid());
        spec_ = dir_.filePath("tiny.json");
        rows_ = dir_.filePath("tiny.jsonl");
        write(spec_, tinyStudy());
        const QString failed = runStudy(spec_, rows_);
        QVERIFY2(failed.isEmpty(), qPrintable(failed));
        cliRows_ = readStudyRows(rows_.toStdString());
        QCOMPARE(cliRows_.size(), std::size_t(12));
    }

    void openShowsTheStudyAndClearsWithoutOne() {
        MainWindow w;
        StudyTab* tab = w.studyTab();
        const QString named =
            projectWith(dir_.filePath("named.json"), {{"spec", spec_}, {"results", rows_}});
        QVERIFY(open(w, named, true));
        QCOMPARE(tab->studyFile(), spec_);
        QCOMPARE(tab->resultsFile(), rows_);
        QCOMPARE(criticalColumn(tab->table()), criticalColumn(cliRows_));
        const std::vector<Fragility> fit = studyFragility(cliRows_, {});
        QCOMPARE(tab->fragility().size(), fit.size());
        for (std::size_t i = 0; i < fit.size(); ++i) {
            QVERIFY(fit[i].fit && tab->fragility()[i].fit);
            QCOMPARE(tab->fragility()[i].fit->median, fit[i].fit->median);
            QCOMPARE(tab->fragility()[i].fit->beta, fit[i].fit->beta);
        }
        QVERIFY(!tab->chartView()->chart()->series().isEmpty());
        QVERIFY(!tab->resultsStale());
        QCOMPARE(tab->rows(), readAll(rows_).toStdString());

        QVERIFY(open(w, kNoStudy, false)); // no study: nothing of the last one stays
        QVERIFY(isCleared(tab));

        // The project names only the study file; its results lie beside it as tiny.jsonl.
        const QString beside = projectWith(dir_.filePath("beside.json"), {{"spec", spec_}});
        QVERIFY(open(w, beside, true));
        QCOMPARE(tab->resultsFile(), rows_);
        QCOMPARE(criticalColumn(tab->table()), criticalColumn(cliRows_));
        w.newProject();
        QVERIFY(isCleared(tab));
    }

    // Rows of mu 0.4, 0.6 named as the results of a study of mu 0.4, 0.5: the tab does not show
    // them and says why; the report refuses them, naming study.results.
    void resultsOfAnotherStudyAreRefused() {
        const QString other = dir_.filePath("other.json");
        write(other, tinyStudy("[0.4, 0.5]"));
        const auto hashed = [](const QString& path) {
            StudySpec s = loadStudy(path.toStdString());
            hashStudyRecords(s); // the rows' fingerprints are checked against the records
            return s;
        };
        const std::string m = studyRowsMismatch(hashed(other), dir_.path().toStdString(), cliRows_);
        QVERIFY2(QString::fromStdString(m).contains("mu = 0.6"), m.c_str());
        QVERIFY(studyRowsMismatch(hashed(spec_), dir_.path().toStdString(), cliRows_).empty());

        const QString project =
            projectWith(dir_.filePath("stale.json"), {{"spec", other}, {"results", rows_}});
        MainWindow w;
        QVERIFY(open(w, project, true));
        StudyTab* tab = w.studyTab();
        QCOMPARE(tab->studyFile(), other);
        QCOMPARE(tab->table()->rowCount(), 0);
        QVERIFY(tab->fragility().empty());
        QVERIFY2(tab->message().contains("not the study's"), qPrintable(tab->message()));

        QProcess p;
        p.start(KINSTAB_CLI, {"report", "--project", project, "--sections", "study", "-o",
                              dir_.filePath("stale.pdf")});
        QVERIFY(p.waitForFinished(120000));
        QCOMPARE(p.exitCode(), 2);
        const QByteArray err = p.readAllStandardError();
        QVERIFY2(err.contains("study.results") && err.contains("mu = 0.6"), err.constData());
        QVERIFY(!QFile::exists(dir_.filePath("stale.pdf")));
    }

    // The same study with another scan step: the rows show the same inputs, but were not
    // computed with this search (issue 31: shown, as the step is in no row). The fingerprint
    // tells them apart, in the tab and in the report.
    void resultsOfAnotherSearchAreRefused() {
        const QString other = dir_.filePath("other-step.json");
        QByteArray text = tinyStudy();
        text.replace("\"scan_step_g\": 0.05", "\"scan_step_g\": 0.04");
        write(other, text);
        const QString project =
            projectWith(dir_.filePath("step.json"), {{"spec", other}, {"results", rows_}});
        MainWindow w;
        QVERIFY(open(w, project, true));
        StudyTab* tab = w.studyTab();
        QCOMPARE(tab->table()->rowCount(), 0);
        QVERIFY2(tab->message().contains("not the study's") &&
                     tab->message().contains("is of study "),
                 qPrintable(tab->message()));
        QProcess p;
        p.start(KINSTAB_CLI, {"report", "--project", project, "--sections", "study", "-o",
                              dir_.filePath("step.pdf")});
        QVERIFY(p.waitForFinished(120000));
        QCOMPARE(p.exitCode(), 2);
        const QByteArray err = p.readAllStandardError();
        QVERIFY2(err.contains("study.results") && err.contains("is of study "), err.constData());
    }

    void useInProjectSaveReopen() {
        MainWindow w;
        QVERIFY(open(w, kNoStudy, false));
        StudyTab* tab = w.studyTab();
        tab->setRecordsFolder(KINSTAB_SOURCE_DIR "/resources/records", "*.AT2", "*UP*, *DWN*");
        tab->setLists("0.4,0.6", "0.099", "");
        tab->setSearch(3.0, 0.05);
        QSignalSpy done(tab, &StudyTab::finished);
        tab->run();
        QVERIFY(done.wait(120000));
        QCOMPARE(tab->table()->rowCount(), 12);
        const QStringList shown = criticalColumn(tab->table());
        QVERIFY(!w.inputHistory()->isModified());

        const QString gui = dir_.filePath("gui-study.json");
        QVERIFY2(tab->useInProject(gui), qPrintable(tab->message()));
        QVERIFY(w.inputHistory()->isModified()); // Open or Quit now ask first
        QVERIFY(w.isWindowModified());
        // Undo takes the study out of the project again; the tab keeps its results. Redo.
        const std::optional<ProjectStudy> used = w.project().study;
        QVERIFY(used && used->spec == gui.toStdString());
        w.inputHistory()->stack()->undo();
        QVERIFY(!w.project().study);
        QVERIFY(!w.inputHistory()->isModified());
        QCOMPARE(criticalColumn(tab->table()), shown);
        w.inputHistory()->stack()->redo();
        QVERIFY(w.project().study == used);
        const QString results = dir_.filePath("gui-study.jsonl");
        QCOMPARE(readAll(results).toStdString(), tab->rows());

        const QString saved = dir_.filePath("saved.json");
        QCOMPARE(w.saveProjectAs(saved), QString());
        const QJsonObject study =
            QJsonDocument::fromJson(readAll(saved)).object()["study"].toObject();
        QCOMPARE(study["spec"].toString(), QStringLiteral("gui-study.json"));
        QCOMPARE(study["results"].toString(), QStringLiteral("gui-study.jsonl"));

        QVERIFY(open(w, kNoStudy, false));
        QVERIFY(isCleared(tab));
        QVERIFY(open(w, saved, true));
        QCOMPARE(tab->studyFile(), gui);
        QCOMPARE(tab->resultsFile(), results);
        QCOMPARE(criticalColumn(tab->table()), shown);
        QVERIFY(w.project().study.has_value()); // the report gets its study section
    }

    // The shipped levels example (a building block, levels and fitted-sine motions, which the
    // tab has no fields for) opens with its results current, not stale, and the table names
    // each row's driving motion as the rows do (core's studyDriverText).
    void levelsStudyOpensWithCurrentResults() {
        const QString spec = KINSTAB_SOURCE_DIR "/resources/examples/study-levels.json";
        const QString rows = dir_.filePath("levels.jsonl");
        const QString failed = runStudy(spec, rows);
        QVERIFY2(failed.isEmpty(), qPrintable(failed));
        const std::vector<StudyRow> cli = readStudyRows(rows.toStdString());
        MainWindow w;
        QVERIFY(open(w,
                     projectWith(dir_.filePath("levels.json"), {{"spec", spec}, {"results", rows}}),
                     true));
        auto* tab = w.studyTab();
        QVERIFY2(!tab->resultsStale(), qPrintable(tab->message()));
        QCOMPARE(tab->table()->rowCount(), static_cast<int>(cli.size()));
        for (int i = 0; i < tab->table()->rowCount(); ++i)
            QCOMPARE(tab->table()->item(i, 3)->text(),
                     QString::fromStdString(studyDriverText(cli[static_cast<std::size_t>(i)])));
        QVERIFY(tab->table()->item(0, 3)->text().startsWith("level "));
        screenshot(w, "study-tab-levels.png");
    }

    // With KINSTAB_SCREENSHOT_DIR=DIR: the window with the Study tab showing the shipped example
    // study and its results (docs/screenshots/study-tab.png), to look at.
    void screenshotOfTheExampleStudy() {
        if (qEnvironmentVariable("KINSTAB_SCREENSHOT_DIR").isEmpty())
            QSKIP("KINSTAB_SCREENSHOT_DIR not set");
        const QString spec = KINSTAB_SOURCE_DIR "/resources/examples/study-example.json";
        const QString rows = dir_.filePath("example.jsonl");
        const QString failed = runStudy(spec, rows);
        QVERIFY2(failed.isEmpty(), qPrintable(failed));
        MainWindow w;
        QVERIFY(
            open(w, projectWith(dir_.filePath("example.json"), {{"spec", spec}, {"results", rows}}),
                 true));
        screenshot(w, "study-tab.png");
    }

    void editingAfterTheRunMarksResultsStale() {
        MainWindow w;
        const QString named =
            projectWith(dir_.filePath("named2.json"), {{"spec", spec_}, {"results", rows_}});
        QVERIFY(open(w, named, true));
        StudyTab* tab = w.studyTab();
        auto* line = tab->findChild<QLabel*>(QStringLiteral("studyStale"));
        QVERIFY(line);
        QVERIFY(!tab->resultsStale());
        QVERIFY(!line->isVisibleTo(tab));
        tab->setLists("0.4", "0.099", "");
        QVERIFY(tab->resultsStale());
        QVERIFY(line->isVisibleTo(tab));
        QVERIFY(line->text().contains("run again"));
        QCOMPARE(tab->table()->rowCount(), 12); // still shown, marked

        // The edited study goes into the project without the stale results: the report runs it.
        QVERIFY2(tab->useInProject(dir_.filePath("edited.json")), qPrintable(tab->message()));
        QVERIFY(w.project().study.has_value());
        QCOMPARE(w.project().study->spec, dir_.filePath("edited.json").toStdString());
        QVERIFY(w.project().study->results.empty());

        tab->setLists("0.4,0.6", "0.099", ""); // back to what the results are for
        QVERIFY(!tab->resultsStale());
        QVERIFY(!line->isVisibleTo(tab));
    }
};

QTEST_MAIN(TestStudyProject)
#include "tst_study_project.moc"
