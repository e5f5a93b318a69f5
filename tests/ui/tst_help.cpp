// SPDX-License-Identifier: GPL-3.0-or-later
// Help → User guide (F1 at the panel in focus), Help → About and File → Open example, offscreen.
// Screenshots of the help window and the About box go to $KINSTAB_SCREENSHOT_DIR when set
// (docs/screenshots/ holds the committed ones), else to a temporary folder.

#include "WindowFields.h"
#include "ui/AboutBox.h"
#include "ui/ExampleProjects.h"
#include "ui/HelpMenu.h"
#include "ui/HelpWindow.h"
#include "ui/MainWindow.h"
#include "ui/NumberField.h"

#include <Eigen/Core>

#include <QDir>
#include <QDockWidget>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMenuBar>
#include <QScrollBar>
#include <QSettings>
#include <QStandardPaths>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTextBlock>
#include <QTextBrowser>
#include <QtTest>

#include <memory>

using namespace kinstab;
using namespace kinstab::ui;

class TestHelp : public QObject {
    Q_OBJECT
private:
    std::unique_ptr<MainWindow> w;
    QTemporaryDir tmp_;
    QString shotDir() const {
        const QString env = qEnvironmentVariable("KINSTAB_SCREENSHOT_DIR");
        return env.isEmpty() ? tmp_.path() : env;
    }
    QAction* action(const char* name) { return w->findChild<QAction*>(QString::fromLatin1(name)); }
    HelpWindow* helpWindow() { return w->findChild<HelpWindow*>(QStringLiteral("helpWindow")); }
    // The heading of the block the help browser's cursor sits in.
    QString shownSection() { return helpWindow()->browser()->textCursor().block().text(); }

private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QSettings().clear();
    }
    void init() {
        w = std::make_unique<MainWindow>();
        w->show();
        QVERIFY(QTest::qWaitForWindowExposed(w.get()));
    }
    void cleanup() { w.reset(); }

    void helpMenuHasGuideOnF1AndAbout() {
        const QList<QAction*> menus = w->menuBar()->actions();
        QCOMPARE(menus.last()->text(), QStringLiteral("&Help"));
        QVERIFY(action("userGuideAction"));
        QCOMPARE(action("userGuideAction")->shortcut(), QKeySequence(QKeySequence::HelpContents));
        QCOMPARE(action("userGuideAction")->shortcut(), QKeySequence(Qt::Key_F1));
        QVERIFY(action("aboutAction"));
    }
    void everyPanelHasItsSection() {
        // Each dock and central tab maps to a heading that exists in the shipped guide, and
        // only widgets outside all of them fall back to the five steps.
        HelpWindow help;
        const QStringList sections = help.sections();
        QVERIFY(sections.contains(QStringLiteral("Your first design check in five steps")));
        int mapped = 0;
        for (QDockWidget* d : w->findChildren<QDockWidget*>()) {
            const QString s = helpSectionFor(d->widget());
            QVERIFY2(sections.contains(s), qPrintable(d->windowTitle() + " -> " + s));
            QVERIFY2(s != QStringLiteral("Your first design check in five steps"),
                     qPrintable(d->windowTitle()));
            ++mapped;
        }
        QVERIFY(mapped >= 10); // six inputs, the verdict and three charts
        auto* tabs = w->findChild<QTabWidget*>();
        QVERIFY(tabs);
        for (int i = 0; i < tabs->count(); ++i) {
            const QString s = helpSectionFor(tabs->widget(i));
            QVERIFY2(sections.contains(s), qPrintable(tabs->tabText(i) + " -> " + s));
        }
        QCOMPARE(helpSectionFor(nullptr), QStringLiteral("Your first design check in five steps"));
    }
    void f1OpensTheSectionOfThePanelInFocus() {
        QLineEdit* stories = testing::namedField(w.get(), "stories")->lineEdit();
        w->activateWindow();
        stories->setFocus();
        QTRY_COMPARE(QApplication::focusWidget(), stories);
        action("userGuideAction")->trigger(); // what F1 does
        QVERIFY(helpWindow() && helpWindow()->isVisible());
        QCOMPARE(shownSection(), QStringLiteral("Building"));
        // The section is scrolled into view, not left at the top of the guide.
        QVERIFY(helpWindow()->browser()->verticalScrollBar()->value() > 0);
        helpWindow()->resize(940, 640);
        QVERIFY(helpWindow()->grab().save(QDir(shotDir()).filePath("help-window.png")));
        // Asked again from another panel, the same window moves to that panel's section.
        QLineEdit* mu = testing::namedField(w.get(), "mu")->lineEdit();
        mu->setFocus();
        showUserGuide(w.get(), helpSectionFor(mu));
        QCOMPARE(w->findChildren<HelpWindow*>().size(), 1);
        QCOMPARE(shownSection(), QStringLiteral("Slab and walls"));
        // The contents list beside the guide shows a section on a click.
        auto* contents = helpWindow()->findChild<QListWidget*>(QStringLiteral("helpContents"));
        QVERIFY(contents);
        const auto items =
            contents->findItems(QStringLiteral("Reading a γc surface"), Qt::MatchExactly);
        QCOMPARE(items.size(), 1);
        emit contents->itemClicked(items.front());
        QCOMPARE(shownSection(), QStringLiteral("Reading a γc surface"));
    }
    void aboutNamesVersionLicenceCitationLibraries() {
        const QString html = aboutHtml();
        for (const QString& s :
             {QStringLiteral("kinstab " KINSTAB_VERSION), QStringLiteral("GPL-3.0-or-later"),
              QStringLiteral("Furgerson"), QStringLiteral("AMES TR-80/002"),
              QStringLiteral("Qt ") + QString::fromLatin1(qVersion()),
              QStringLiteral("Eigen %1.%2.%3")
                  .arg(EIGEN_WORLD_VERSION)
                  .arg(EIGEN_MAJOR_VERSION)
                  .arg(EIGEN_MINOR_VERSION),
              QStringLiteral("nlohmann/json")})
            QVERIFY2(html.contains(s), qPrintable(s));
        AboutBox box(w.get());
        box.show();
        QVERIFY(QTest::qWaitForWindowExposed(&box));
        QCOMPARE(box.findChild<QLabel*>(QStringLiteral("aboutText"))->text(), html);
        QVERIFY(box.grab().save(QDir(shotDir()).filePath("about-box.png")));
    }
    void openExamples_data() {
        QTest::addColumn<int>("index");
        QTest::addColumn<QString>("model");
        QTest::addColumn<bool>("record");
        QTest::newRow("paper 16-story") << 0 << "slab1d" << false;
        QTest::newRow("Pacoima Dam record") << 1 << "slab1d" << true;
        QTest::newRow("floors") << 2 << "slab1d" << true;
        QTest::newRow("blocks") << 3 << "slab1d" << true;
        QTest::newRow("study") << 4 << "slab1d" << false;
        QTest::newRow("risk") << 5 << "slab1d" << false;
        QTest::newRow("planar") << 6 << "planar" << false;
    }
    void openExamples() {
        // Copied out of the resources with the records they name, then opened as a user would:
        // a record example's relative path must resolve beside the copy.
        QFETCH(int, index);
        QFETCH(QString, model);
        QFETCH(bool, record);
        QTemporaryDir dir;
        QString error;
        const QString path = copyExample(exampleProjects().at(index), dir.path(), &error);
        QVERIFY2(!path.isEmpty(), qPrintable(error));
        QVERIFY(path.startsWith(dir.path()));
        QVERIFY(w->openProject(path, true));
        const Project p = w->project();
        QCOMPARE(QString::fromLatin1(modelKindName(p.model)), model);
        QCOMPARE(p.record.has_value(), record);
        QCOMPARE(p.building.stories, 16); // the paper's building in every example
        // Copying again replaces the copy (a user's edits to an example do not block it).
        QVERIFY(!copyExample(exampleProjects().at(index), dir.path(), &error).isEmpty());
    }
    void exampleMenuListsEveryExample() {
        auto* menu = w->findChild<QMenu*>(QStringLiteral("exampleMenu"));
        QVERIFY(menu);
        QCOMPARE(menu->actions().size(), static_cast<int>(exampleProjects().size()));
    }
};

QTEST_MAIN(TestHelp)
#include "tst_help.moc"
