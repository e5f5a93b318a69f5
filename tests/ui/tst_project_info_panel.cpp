// SPDX-License-Identifier: GPL-3.0-or-later
// File → Project information… (ui/ProjectInfoPanel.h) and the export's section choice
// (ui/ReportSectionsDialog.h): what the user types is what the project and the report get; text
// the project file would refuse is named beside its field (ui/TextField.h), also the building's
// name (ui/BuildingPanel.h).

#include "ui/BuildingPanel.h"
#include "ui/ProjectInfoPanel.h"
#include "ui/ReportSectionsDialog.h"

#include <QCheckBox>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
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
    // Issue 31: what the project file refuses is named beside the field as it is typed, in
    // characters (not the UTF-16 units of QLineEdit::maxLength, which cut 150 emoji to 100).
    void fieldsSayWhatIsWrong() {
        ProjectInfoPanel panel;
        QLineEdit* e = panel.findChild<QLineEdit*>("registration");
        QLabel* message = qobject_cast<QLabel*>(e->parentWidget()->findChild<QLabel*>("textError"));
        QVERIFY(message && message->isHidden());
        e->setText(QString::fromUtf8("S 12345\u202E67890"));
        QVERIFY(!message->isHidden());
        QCOMPARE(message->text(),
                 QString("contains U+202E (a bidirectional override) at character 8"));
        QCOMPARE(panel.problem(), "info.registration: " + message->text());
        e->setText(QString(201, QChar('x')));
        QCOMPARE(message->text(), QString("201 characters, more than the limit of 200"));
        QString emoji;
        for (int i = 0; i < 200; ++i)
            emoji += QString::fromUtf8("\U0001F3D7"); // 400 UTF-16 units, 200 characters
        e->setText(emoji);
        QVERIFY(message->isHidden());
        QCOMPARE(panel.info().registration.size(), std::size_t(800)); // nothing cut
        QVERIFY(panel.problem().isEmpty());
        // A revision's text is checked as it is typed too, under the table.
        QTableWidget* t = panel.findChild<QTableWidget*>("revisions");
        QLabel* revisionError = panel.findChild<QLabel*>("revisionsError");
        QPushButton* add = nullptr;
        for (QPushButton* b : panel.findChildren<QPushButton*>())
            if (b->text().contains("Add")) add = b;
        QVERIFY(add);
        add->click();
        QVERIFY(revisionError->isHidden());
        t->item(0, 2)->setText(QString::fromUtf8("Issued \u2067for\u2069 permit"));
        QVERIFY(!revisionError->isHidden());
        QCOMPARE(revisionError->text(), QString("info.revisions[0].description: contains U+2067 "
                                                "(a bidirectional isolate) at character 8"));
    }
    void buildingNameSaysWhatIsWrong() {
        BuildingPanel panel;
        QLineEdit* name = panel.findChild<QWidget*>("buildingName")->findChild<QLineEdit*>();
        name->setText(QString::fromUtf8("Tower\x1b[31m"));
        QVERIFY(!panel.isValid());
        QCOMPARE(panel.problems(),
                 QStringList{"Name: contains U+001B (a control character) at character 6"});
        name->setText("Tower A");
        QVERIFY(panel.isValid());
        QCOMPARE(panel.building().name, std::string("Tower A"));
    }
    void sectionDialogStartsFromTheDefault() {
        using namespace kinstab::report;
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
