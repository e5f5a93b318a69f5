// SPDX-License-Identifier: GPL-3.0-or-later
// The Records tab under a planar project (issue #18): the planar model takes the record as the
// slab's vertical base motion as recorded, so the preview must not pass it through the
// horizontal floor filter; a 1-DOF project gets the filter back.

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

    void planarProjectShowsTheRecordUnfiltered() {
        MainWindow w; // the paper's 1-DOF example
        RecordPreview* preview = w.findChild<RecordsTab*>()->preview();
        auto* filter = preview->findChild<QCheckBox*>();
        QVERIFY(filter);
        QVERIFY(filter->isEnabled());
        QVERIFY(preview->floorFilter()); // on by default for a floor slab
        QVERIFY(preview->floorMotion());

        QVERIFY(w.openProject(QStringLiteral(":/examples/paper-planar.json")));
        QVERIFY(!filter->isEnabled());
        QVERIFY(!preview->floorFilter());
        QVERIFY(!preview->floorMotion()); // the envelope is fitted to the record itself
        preview->setFloorFilter(kinstab::FloorFilterParams{1.0, 0.02, std::nullopt});
        QVERIFY(!preview->floorFilter()); // still off while the project is planar

        w.newProject(); // 1-DOF again
        QVERIFY(filter->isEnabled());
    }
};

QTEST_MAIN(TestRecordsPlanar)
#include "tst_records_planar.moc"
