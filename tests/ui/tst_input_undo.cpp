// SPDX-License-Identifier: GPL-3.0-or-later
// Undo/redo of the inputs (issue #18): typing into a field is one step, a checkbox and a combo
// are steps of their own, Ctrl+Z / Ctrl+Shift+Z work even with the focus in a text field, and
// the title's modified mark follows the saved state.

#include "core/io/Project.h"
#include "ui/BuildingPanel.h"
#include "ui/ExcitationPanel.h"
#include "ui/InputHistory.h"
#include "ui/MainWindow.h"
#include "ui/NumberField.h"
#include "ui/SlabPanel.h"

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QLineEdit>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QtTest>

#include <nlohmann/json.hpp>

using namespace kinstab;
using namespace kinstab::ui;

namespace {

std::string inputs(const MainWindow& w) {
    return projectToJson(w.project()).dump();
}

QLineEdit* field(const MainWindow& w, const char* name) {
    auto* f = w.slabPanel()->findChild<NumberField*>(QString::fromLatin1(name));
    return f ? f->lineEdit() : nullptr;
}

// Shown and active, as in use: keystrokes merge by the field that has the focus.
void showActive(MainWindow& w) {
    w.show();
    w.activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(&w));
}

void retype(QLineEdit* e, const QString& text) {
    e->setFocus();
    e->selectAll();
    QTest::keyClicks(e, text);
}

} // namespace

class TestInputUndo : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QSettings().clear(); // a first start: the paper's example
    }

    void typingIsOneStepAndTheKeysUndoIt() {
        MainWindow w;
        showActive(w);
        QUndoStack* stack = w.inputHistory()->stack();
        QCOMPARE(stack->count(), 0);
        QVERIFY(!w.isWindowModified());
        QVERIFY(w.windowTitle().contains(QStringLiteral("[*]")));
        const std::string before = inputs(w);
        QLineEdit* mu = field(w, "mu");
        QVERIFY(mu);
        const QString old = mu->text();
        retype(mu, QStringLiteral("0.55"));
        QCOMPARE(stack->count(), 1); // "0", "0.", "0.5", "0.55": one step
        QVERIFY(w.isWindowModified());
        QCOMPARE(w.currentCase().slab.mu, 0.55);

        QTest::keyClick(mu, Qt::Key_Z, Qt::ControlModifier); // focus still in the field
        QCOMPARE(mu->text().toDouble(), old.toDouble());
        QCOMPARE(inputs(w), before);
        QVERIFY(!w.isWindowModified()); // back at the saved state
        QTest::keyClick(mu, Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
        QCOMPARE(w.currentCase().slab.mu, 0.55);
        QVERIFY(w.isWindowModified());
    }

    void fieldsCheckboxesAndCombosAreSeparateSteps() {
        MainWindow w;
        showActive(w);
        QUndoStack* stack = w.inputHistory()->stack();
        const std::string s0 = inputs(w);
        retype(field(w, "mu"), QStringLiteral("0.45"));
        const std::string s1 = inputs(w);
        retype(field(w, "tstar"), QStringLiteral("1.5"));
        const std::string s2 = inputs(w);
        auto* estimate = w.buildingPanel()->findChild<QCheckBox*>();
        QVERIFY(estimate);
        QTest::mouseClick(estimate, Qt::LeftButton, {}, QPoint(6, estimate->height() / 2));
        const std::string s3 = inputs(w);
        // The building's occupancy (the last of its lists): every choice is a valid input.
        QComboBox* combo = w.buildingPanel()->findChildren<QComboBox*>().last();
        QVERIFY(combo && combo->count() > 1);
        combo->setFocus(); // as a click on it would
        combo->setCurrentIndex((combo->currentIndex() + 1) % combo->count());
        const std::string s4 = inputs(w);
        QCOMPARE(stack->count(), 4);
        for (const std::string& s : {s1, s2, s3, s4})
            QVERIFY(!s.empty());
        QVERIFY(s0 != s1 && s1 != s2 && s2 != s3 && s3 != s4);
        const std::string back[] = {s3, s2, s1, s0};
        for (const std::string& s : back) {
            stack->undo();
            QCOMPARE(inputs(w), s);
        }
        QVERIFY(!w.isWindowModified());
        stack->redo();
        stack->redo();
        QCOMPARE(inputs(w), s2);
        QCOMPARE(stack->count(), 4); // undo/redo do not record steps of their own
    }

    // View → Units is kept in the project file, so a switch is a step that undo takes back: the
    // fields, the menu's mark and the file's units all return.
    void unitsSwitchIsAStep() {
        MainWindow w;
        showActive(w);
        QUndoStack* stack = w.inputHistory()->stack();
        QCOMPARE(stack->count(), 0);
        auto* si = w.findChild<QAction*>(QStringLiteral("unitsSI"));
        auto* us = w.findChild<QAction*>(QStringLiteral("unitsUS"));
        QVERIFY(si && us);
        if (si->isChecked()) us->trigger(); // start from US; a first step when it was SI
        const int start = stack->count();
        const std::string before = inputs(w);
        QCOMPARE(projectUnits(w.project()), UnitSystem::US);
        si->trigger();
        QCOMPARE(stack->count(), start + 1);
        QCOMPARE(projectUnits(w.project()), UnitSystem::SI);
        QVERIFY(w.isWindowModified() || start > 0);
        stack->undo();
        QCOMPARE(inputs(w), before);
        QVERIFY(us->isChecked());
        QVERIFY(!si->isChecked());
        stack->redo();
        QCOMPARE(projectUnits(w.project()), UnitSystem::SI);
        QVERIFY(si->isChecked());
    }

    void savingClearsTheMarkAndOpeningClearsTheHistory() {
        MainWindow w;
        showActive(w);
        retype(field(w, "mu"), QStringLiteral("0.65"));
        QVERIFY(w.isWindowModified());
        const QString path = dir_.filePath("p.json");
        QCOMPARE(w.saveProjectAs(path), QString());
        QVERIFY(!w.isWindowModified());
        QVERIFY(w.inputHistory()->stack()->canUndo()); // saving keeps the history
        w.inputHistory()->stack()->undo();
        QVERIFY(w.isWindowModified()); // now differs from the file
        QVERIFY(w.openProject(path));
        QVERIFY(!w.isWindowModified());
        QCOMPARE(w.inputHistory()->stack()->count(), 0);
        QCOMPARE(w.currentCase().slab.mu, 0.65);
    }
};

QTEST_MAIN(TestInputUndo)
#include "tst_input_undo.moc"
