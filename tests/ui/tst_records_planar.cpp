// SPDX-License-Identifier: GPL-3.0-or-later
// The Records tab under a planar project (issue #18): the planar model takes the record as the
// slab's vertical base motion as recorded, so the preview must not pass it through the
// horizontal floor filter; a 1-DOF project gets the filter back.

#include "core/io/Project.h"
#include "ui/MainWindow.h"
#include "ui/RecordPreview.h"
#include "ui/RecordsTab.h"

#include <QCheckBox>
#include <QSettings>
#include <QStandardPaths>
#include <QtTest>

using namespace kinstab::ui;

class TestRecordsPlanar : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QSettings().clear();
    }

    // The tab shows the open project's record (issue 30): none for the enveloped sine, the
    // record example's Pacoima Dam 164 through its floor filter, a planar project's vertical
    // motion unfiltered, and nothing of the previous project after Open or New.
    void theTabShowsTheProjectsRecord() {
        MainWindow w; // the paper's 1-DOF example: the enveloped sine, no record
        auto* tab = w.findChild<RecordsTab*>();
        RecordPreview* preview = tab->preview();
        auto* filter = preview->findChild<QCheckBox*>();
        QVERIFY(filter);
        QVERIFY(!preview->record());
        QVERIFY(tab->messageText().contains("no record"));

        QVERIFY(w.openProject(KINSTAB_SOURCE_DIR "/resources/examples/paper-16-story-record.json"));
        QVERIFY(preview->record());
        QVERIFY2(preview->record()->name.find("Pacoima") != std::string::npos,
                 preview->record()->name.c_str());
        QVERIFY(filter->isEnabled());
        const auto f = preview->floorFilter();
        QVERIFY(f && f->period == 1.0 && std::abs(f->damping - 0.02) < 1e-12);
        QVERIFY(preview->floorMotion());

        kinstab::Project planar =
            kinstab::loadProject(KINSTAB_SOURCE_DIR "/resources/examples/paper-planar.json");
        QVERIFY(w.openProject(QStringLiteral(":/examples/paper-planar.json")));
        QVERIFY(!filter->isEnabled());
        QVERIFY(!preview->floorFilter());
        QCOMPARE(bool(preview->record()), planar.planar.vertical != kinstab::VerticalSource::None);
        preview->setFloorFilter(kinstab::FloorFilterParams{1.0, 0.02, std::nullopt});
        QVERIFY(!preview->floorFilter()); // still off while the project is planar

        w.newProject(); // 1-DOF again, no record
        QVERIFY(filter->isEnabled());
        QVERIFY(!preview->record());
    }
};

QTEST_MAIN(TestRecordsPlanar)
#include "tst_records_planar.moc"
