// SPDX-License-Identifier: GPL-3.0-or-later
// The unsaved-changes guard (issue #18): New, Open and Quit ask Save / Discard / Cancel when
// the inputs differ from the file; Cancel keeps everything; the next start opens the file as
// last saved, and unsaved inputs only when the user chose "Keep for next start".

#include "ui/InputHistory.h"
#include "ui/MainWindow.h"
#include "ui/NumberField.h"
#include "ui/SlabPanel.h"

#include <QAbstractButton>
#include <QApplication>
#include <QLineEdit>
#include <QMenuBar>
#include <QMessageBox>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTimer>
#include <QUndoStack>
#include <QtTest>

using namespace kinstab;
using namespace kinstab::ui;

namespace {

void setMu(MainWindow& w, const QString& text) {
    QLineEdit* e = w.slabPanel()->findChild<NumberField*>(QStringLiteral("mu"))->lineEdit();
    e->setFocus();
    e->selectAll();
    QTest::keyClicks(e, text);
}

// Answers the next unsaved-changes box by clicking the button whose text starts with `answer`
// (as shown: "Save", "Discard", "Cancel", "Keep for next start"); counts the boxes seen.
struct Answer {
    int seen = 0;
    QTimer timer;
    explicit Answer(const QString& answer) {
        QObject::connect(&timer, &QTimer::timeout, [this, answer] {
            for (QWidget* top : QApplication::topLevelWidgets()) {
                auto* box = qobject_cast<QMessageBox*>(top);
                if (!box || !box->isVisible() || box->objectName() != "unsavedChangesBox") continue;
                for (QAbstractButton* b : box->buttons())
                    if (b->text().remove('&').startsWith(answer)) {
                        ++seen;
                        b->click();
                        return;
                    }
            }
        });
        timer.start(20);
    }
};

// Opens `path`, types μ, quits answering `answer`: true when the box came once and the window
// closed.
bool editAndQuit(const QString& path, const QString& mu, const QString& answer) {
    MainWindow w;
    if (!w.openProject(path)) return false;
    w.show();
    setMu(w, mu);
    Answer a(answer);
    const bool closed = w.close();
    return closed && a.seen == 1;
}

QAction* fileAction(MainWindow& w, const QString& text) {
    for (QAction* a : w.menuBar()->actions().first()->menu()->actions())
        if (a->text().remove('&').startsWith(text)) return a;
    return nullptr;
}

} // namespace

class TestUnsavedChanges : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;
    QString path_;

private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QSettings().clear();
        path_ = dir_.filePath("slab.json");
        MainWindow w;
        setMu(w, "0.55");
        QCOMPARE(w.saveProjectAs(path_), QString()); // the saved file: mu = 0.55
    }

    void init() { QSettings().clear(); }

    void newAsksAndCancelKeepsTheEdits() {
        MainWindow w;
        QVERIFY(w.openProject(path_));
        w.show();
        setMu(w, "0.7");
        Answer cancel("Cancel");
        fileAction(w, "New")->trigger();
        QCOMPARE(cancel.seen, 1);
        QCOMPARE(w.currentCase().slab.mu, 0.7);
        QVERIFY(w.isWindowModified());
        QCOMPARE(w.projectPath(), path_);
    }

    void newWithDiscardStartsAfresh() {
        MainWindow w;
        QVERIFY(w.openProject(path_));
        w.show();
        setMu(w, "0.7");
        Answer discard("Discard");
        fileAction(w, "New")->trigger();
        QCOMPARE(discard.seen, 1);
        QVERIFY(w.projectPath().isEmpty());
        QVERIFY(!w.isWindowModified());
    }

    void unmodifiedNewDoesNotAsk() {
        MainWindow w;
        QVERIFY(w.openProject(path_));
        w.show();
        Answer any("Cancel");
        fileAction(w, "New")->trigger();
        QCOMPARE(any.seen, 0);
        QVERIFY(w.projectPath().isEmpty());
    }

    void quitCancelKeepsTheWindowOpen() {
        MainWindow w;
        QVERIFY(w.openProject(path_));
        w.show();
        setMu(w, "0.7");
        Answer cancel("Cancel");
        QVERIFY(!w.close());
        QCOMPARE(cancel.seen, 1);
        QVERIFY(w.isVisible());
    }

    void quitSaveWritesTheFile() {
        const QString other = dir_.filePath("saved-at-quit.json");
        QFile::copy(path_, other);
        QVERIFY(editAndQuit(other, "0.65", "Save"));
        MainWindow next; // the next start: the saved file, with the edit in it
        QCOMPARE(next.projectPath(), other);
        QCOMPARE(next.currentCase().slab.mu, 0.65);
        QVERIFY(!next.isWindowModified());
    }

    void quitDiscardRestoresTheSavedFileNextTime() {
        QVERIFY(editAndQuit(path_, "0.7", "Discard"));
        MainWindow next;
        QCOMPARE(next.projectPath(), path_);
        QCOMPARE(next.currentCase().slab.mu, 0.55); // not the discarded 0.7
        QVERIFY(!next.isWindowModified());
    }

    void quitKeepBringsTheEditsBackAsUnsaved() {
        QVERIFY(editAndQuit(path_, "0.7", "Keep for next start"));
        MainWindow next;
        QCOMPARE(next.projectPath(), path_);
        QCOMPARE(next.currentCase().slab.mu, 0.7);
        QVERIFY(next.isWindowModified()); // marked: they are not in the file
        next.inputHistory()->stack()->undo();
        QCOMPARE(next.currentCase().slab.mu, 0.55); // one undo back to the file
    }
};

QTEST_MAIN(TestUnsavedChanges)
#include "tst_unsaved_changes.moc"
