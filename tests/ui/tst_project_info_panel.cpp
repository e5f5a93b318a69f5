// SPDX-License-Identifier: GPL-3.0-or-later
// File → Project information… (ui/ProjectInfoPanel.h) and the export's section choice
// (ui/ReportSectionsDialog.h): what the user types is what the project and the report get.

#include "ui/ProjectInfoPanel.h"
#include "ui/ReportSectionsDialog.h"

#include <QCheckBox>
#include <QLineEdit>
#include <QTableWidget>
#include <QtTest>

using namespace kinstab;
using namespace kinstab::ui;

class TestProjectInfoPanel : public QObject {
    Q_OBJECT
private slots:
    void showsAndReturnsTheInfo() {
        ProjectInfo in;
        in.engineer = "A. N. Example";
        in.checkedBy = "B. C. Checker";
        in.revisions = {{"0", "2026-11-02", "Issued for review"}};
        ProjectInfoPanel panel;
        panel.setInfo(in);
        QCOMPARE(panel.findChild<QLineEdit*>("engineer")->text(), QString("A. N. Example"));
        QCOMPARE(panel.findChild<QTableWidget*>("revisions")->rowCount(), 1);
        // Typed: the client, with stray blanks; a second revision.
        panel.findChild<QLineEdit*>("client")->setText("  Example Owner  ");
        QTableWidget* t = panel.findChild<QTableWidget*>("revisions");
        t->insertRow(1);
        t->setItem(1, 0, new QTableWidgetItem("A"));
        t->setItem(1, 1, new QTableWidgetItem("2026-11-24"));
        t->setItem(1, 2, new QTableWidgetItem("For permit"));
        const ProjectInfo out = panel.info();
        QCOMPARE(out.client, std::string("Example Owner"));
        QCOMPARE(out.checkedBy, std::string("B. C. Checker"));
        QCOMPARE(out.revisions.size(), std::size_t(2));
        QCOMPARE(out.revisions[1].description, std::string("For permit"));
        QVERIFY(validateProjectInfo(out).empty());
        // KINSTAB_SHOT_DIR set: the panel as the user sees it (docs/screenshots/project-info.png).
        if (const QString dir = qEnvironmentVariable("KINSTAB_SHOT_DIR"); !dir.isEmpty()) {
            panel.resize(560, 480);
            QVERIFY(panel.grab().save(dir + "/project-info.png"));
        }
        // A date the report could not print the same way everywhere is named.
        t->item(1, 1)->setText("24/11/2026");
        QVERIFY(QString::fromStdString(validateProjectInfo(panel.info()))
                    .contains("info.revisions[1].date"));
    }
    void fieldsAreLimited() {
        ProjectInfoPanel panel;
        QLineEdit* e = panel.findChild<QLineEdit*>("siteAddress");
        QCOMPARE(e->maxLength(), 200); // limits::kMaxNameChars
    }
    void sectionDialogStartsFromTheDefault() {
        using namespace kinstab::ui::report;
        ReportSectionsDialog d(defaultSections());
        QCOMPARE(d.sections(), defaultSections());
        d.findChild<QCheckBox*>("section_numerics")->setChecked(false);
        SectionSet expected = defaultSections();
        expected.erase("numerics");
        QCOMPARE(d.sections(), expected);
    }
};

QTEST_MAIN(TestProjectInfoPanel)
#include "tst_project_info_panel.moc"
