// SPDX-License-Identifier: GPL-3.0-or-later
// The Study tab opening a study file (docs/studies.md): the fields show the file, the study
// they describe expands to the same records and parameters as the file (settings the fields do
// not show, such as the search tolerance, kept), a study the tab cannot show is refused with the
// reason, and "Use in project" hands on the file, or first saves edited fields.

#include "core/io/StudySpecJson.h"
#include "core/study/StudyCase.h"
#include "core/study/StudySpec.h"
#include "ui/StudyTab.h"

#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>

using namespace kinstab;
using namespace kinstab::ui;

namespace {

const QString kExample =
    QStringLiteral(KINSTAB_SOURCE_DIR "/resources/examples/study-example.json");
const QString kSmall = QStringLiteral(KINSTAB_TEST_DATA "/study/small-study.json");

std::vector<std::string> recordFiles(const StudySpec& s) {
    std::vector<std::string> out;
    for (const StudyRecord& r : s.records)
        out.push_back(r.file);
    return out;
}

} // namespace

class TestStudyOpen : public QObject {
    Q_OBJECT
private slots:
    void openFillsTheFieldsFaithfully() {
        for (const QString& path : {kExample, kSmall}) {
            StudyTab tab;
            QVERIFY2(tab.openStudy(path), qPrintable(tab.message()));
            const StudySpec file = loadStudy(path.toStdString());
            const StudySpec shown = studyFromJsonText(tab.studyJson(), "");
            QCOMPARE(recordFiles(shown), recordFiles(file));
            QCOMPARE(shown.mu, file.mu);
            QCOMPARE(shown.tstar, file.tstar);
            QCOMPARE(shown.floors.size(), file.floors.size());
            QCOMPARE(studyCaseCount(shown), studyCaseCount(file));
            QCOMPARE(intensityName(shown.intensity), intensityName(file.intensity));
            QCOMPARE(shown.search.to, file.search.to);
            QCOMPARE(shown.search.scanStep, file.search.scanStep);
            QCOMPARE(shown.search.tolerance, file.search.tolerance); // not a field: kept
        }
    }

    void badFileIsRefusedWithTheReason() {
        StudyTab tab;
        QVERIFY(!tab.openStudy(KINSTAB_SOURCE_DIR "/resources/examples/paper-16-story.json"));
        QVERIFY2(tab.message().contains("paper-16-story.json"), qPrintable(tab.message()));
        QVERIFY(tab.studyFile().isEmpty());
    }

    void useInProjectHandsOnTheFile() {
        StudyTab tab;
        QSignalSpy chosen(&tab, &StudyTab::studyChosen);
        QVERIFY(!tab.useInProject({})); // nothing opened, nowhere to save
        QCOMPARE(chosen.count(), 0);
        QVERIFY(tab.openStudy(kExample));
        QVERIFY(tab.useInProject({}));
        QCOMPARE(chosen.count(), 1);
        QCOMPARE(chosen.at(0).at(0).toString(), QFileInfo(kExample).absoluteFilePath());
        // Edited fields are saved first, and that file is the project's study.
        tab.setLists("0.5", "0.099", "");
        QVERIFY(!tab.useInProject({}));
        QTemporaryDir dir;
        const QString saved = dir.filePath("edited.json");
        QVERIFY2(tab.useInProject(saved), qPrintable(tab.message()));
        QCOMPARE(chosen.count(), 2);
        QCOMPARE(chosen.at(1).at(0).toString(), saved);
        QCOMPARE(loadStudy(saved.toStdString()).mu, std::vector<double>{0.5});
    }
};

QTEST_MAIN(TestStudyOpen)
#include "tst_study_open.moc"
