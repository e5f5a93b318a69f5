// SPDX-License-Identifier: GPL-3.0-or-later
// The main window on a 1280 × 800 screen (issue 35): the window with its frame inside the
// screen's available geometry and the status bar on it; the Teaching transport and the slider
// values shown whole, in the window and in presentation mode; the Numerics, Friction, Floors
// and Study tabs with plots of a usable height, tables with rows and unclipped buttons; File →
// Open example offering every project in resources/examples, each opening from its copy.
//
// The offscreen platform is given one 1280 × 800 screen (its JSON configuration, written here
// before QApplication starts) whose windows have a frame, as a window manager's would.

#include "ui/ExampleProjects.h"
#include "ui/MainWindow.h"
#include "ui/NumericsView.h"
#include "ui/ScreenFit.h"
#include "ui/StudyTab.h"
#include "ui/teaching/PresentationMode.h"
#include "ui/teaching/TeachingView.h"

#include <QAbstractButton>
#include <QApplication>
#include <QChartView>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QHeaderView>
#include <QJsonDocument>
#include <QJsonObject>
#include <QMenu>
#include <QScreen>
#include <QScrollArea>
#include <QScrollBar>
#include <QSettings>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTabWidget>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QToolButton>
#include <QtTest>

#include <memory>

using namespace kinstab;
using namespace kinstab::ui;

namespace {

// The part of w on screen: its rectangle clipped by every ancestor (scroll area viewports
// included) and by the screen, in global coordinates.
QRect shownRect(const QWidget* w) {
    QRect r(w->mapToGlobal(QPoint(0, 0)), w->size());
    for (const QWidget* p = w->parentWidget(); p; p = p->parentWidget())
        r &= QRect(p->mapToGlobal(QPoint(0, 0)), p->size());
    return r & w->screen()->availableGeometry();
}

// Shown whole: visible, at least its size hint's height, and not clipped by anything.
QString cut(const QWidget* w) {
    if (!w->isVisible()) return QStringLiteral("%1 hidden").arg(w->objectName());
    if (w->height() < w->sizeHint().height() || w->width() < w->minimumSizeHint().width())
        return QStringLiteral("%1 %2×%3 below its hint %4×%5")
            .arg(w->objectName())
            .arg(w->width())
            .arg(w->height())
            .arg(w->minimumSizeHint().width())
            .arg(w->sizeHint().height());
    if (shownRect(w).size() != w->size())
        return QStringLiteral("%1 shown %2×%3 of %4×%5")
            .arg(w->objectName())
            .arg(shownRect(w).width())
            .arg(shownRect(w).height())
            .arg(w->width())
            .arg(w->height());
    return {};
}

void showTab(MainWindow& w, const QString& title) {
    auto* tabs = w.findChild<QTabWidget*>();
    for (int i = 0; i < tabs->count(); ++i)
        if (tabs->tabText(i) == title) tabs->setCurrentIndex(i);
    QTest::qWait(100);
}

QWidget* currentTab(MainWindow& w) {
    return w.findChild<QTabWidget*>()->currentWidget();
}

} // namespace

class TstScreen1280 : public QObject {
    Q_OBJECT
    std::unique_ptr<MainWindow> w;

private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QSettings().clear(); // a first start
        QCOMPARE(QGuiApplication::primaryScreen()->availableGeometry().size(), QSize(1280, 800));
        w = std::make_unique<MainWindow>();
        // A saved size as large as the screen, as an older version left it.
        w->resize(1280, 800);
        w->show();
        QVERIFY(QTest::qWaitForWindowExposed(w.get()));
        QTest::qWait(600); // past the second fit, once the frame is known
        QVERIFY(!w->windowHandle()->frameMargins().isNull());
    }
    void cleanupTestCase() { w.reset(); }

    void windowAndStatusBarFitTheScreen() {
        const QRect screen = w->screen()->availableGeometry();
        QVERIFY2(screen.contains(w->frameGeometry()),
                 qPrintable(QStringLiteral("frame %1,%2 %3×%4")
                                .arg(w->frameGeometry().x())
                                .arg(w->frameGeometry().y())
                                .arg(w->frameGeometry().width())
                                .arg(w->frameGeometry().height())));
        const QString bar = cut(w->statusBar());
        QVERIFY2(bar.isEmpty(), qPrintable(bar));
        for (QWidget* child : w->statusBar()->findChildren<QWidget*>(Qt::FindDirectChildrenOnly))
            if (child->isVisible())
                QCOMPARE(shownRect(child).size(), child->size()); // progress, time left, text
    }

    // The first size on screens of other sizes (the expected values are 85 % of the available
    // geometry, worked by hand: 0.85 × 1920 = 1632, 0.85 × 1080 = 918, 0.85 × 1040 = 884).
    void openingSizeFollowsTheScreen_data() {
        QTest::addColumn<QRect>("available");
        QTest::addColumn<QSize>("expected");
        QTest::addRow("laptop 1280x800") << QRect(0, 0, 1280, 800) << QSize(1280, 800);
        QTest::addRow("small 1024x600") << QRect(0, 0, 1024, 600) << QSize(1024, 600);
        QTest::addRow("1366x768") << QRect(0, 0, 1366, 768) << QSize(1280, 768);
        QTest::addRow("1920x1080") << QRect(0, 0, 1920, 1080) << QSize(1632, 918);
        QTest::addRow("1920x1080 less a panel") << QRect(0, 40, 1920, 1040) << QSize(1632, 884);
    }
    void openingSizeFollowsTheScreen() {
        QFETCH(QRect, available);
        QFETCH(QSize, expected);
        QCOMPARE(openingSize(available), expected);
    }

    void teachingTransportAndValuesWhole() {
        showTab(*w, QStringLiteral("Teaching"));
        auto* transport = w->teachingView()->findChild<QWidget*>(QStringLiteral("transport"));
        QVERIFY(transport);
        QStringList problems;
        for (QWidget* c : transport->findChildren<QWidget*>())
            if (qobject_cast<QToolButton*>(c) || qobject_cast<QComboBox*>(c) ||
                qobject_cast<QSlider*>(c))
                if (const QString why = cut(c); !why.isEmpty())
                    problems << c->metaObject()->className() + QStringLiteral(" ") + why;
        for (const char* name : {"aValue", "fValue", "muValue", "dValue"}) {
            auto* spin = w->teachingView()->findChild<QDoubleSpinBox*>(QString::fromLatin1(name));
            QVERIFY2(spin, name);
            if (const QString why = cut(spin); !why.isEmpty()) problems << why;
            // The value with its unit, at the widest the range allows, fits the box.
            if (spin->width() < spin->sizeHint().width())
                problems << QStringLiteral("%1 %2 px wide, needs %3")
                                .arg(name)
                                .arg(spin->width())
                                .arg(spin->sizeHint().width());
        }
        QVERIFY2(problems.isEmpty(), qPrintable(problems.join(QStringLiteral("; "))));
    }

    void presentationModeWhole() {
        auto* mode = w->findChild<PresentationMode*>(QStringLiteral("presentationMode"));
        QVERIFY(mode);
        mode->enter();
        QTest::qWait(300);
        QStringList problems;
        auto* transport = w->teachingView()->findChild<QWidget*>(QStringLiteral("transport"));
        for (QWidget* c : transport->findChildren<QWidget*>())
            if (qobject_cast<QToolButton*>(c) || qobject_cast<QComboBox*>(c))
                if (const QString why = cut(c); !why.isEmpty()) problems << why;
        mode->leave();
        QTest::qWait(300);
        QVERIFY2(problems.isEmpty(), qPrintable(problems.join(QStringLiteral("; "))));
        const QRect frame = w->frameGeometry();
        QVERIFY2(w->screen()->availableGeometry().contains(frame),
                 qPrintable(QStringLiteral("frame %1,%2 %3×%4 after leaving")
                                .arg(frame.x())
                                .arg(frame.y())
                                .arg(frame.width())
                                .arg(frame.height())));
    }

    void toolTabsUsable_data() {
        QTest::addColumn<QString>("tab");
        for (const char* t : {"Numerics", "Friction", "Floors", "Study"})
            QTest::newRow(t) << QString::fromLatin1(t);
    }
    void toolTabsUsable() {
        QFETCH(QString, tab);
        showTab(*w, tab);
        QWidget* page = currentTab(*w);
        QStringList problems;
        if (tab == QLatin1String("Numerics")) {
            auto* numerics = qobject_cast<NumericsView*>(page); // the tab itself
            QVERIFY(numerics);
            // A study's worth of lines (six cases, three solvers, three settings each): the
            // plot itself, inside title, legend and axes, keeps a readable height.
            WorkPrecisionStudy study;
            for (const char* c : {"paper-1Hz", "grazing", "chattering", "high-f", "long", "x"})
                for (const char* s : {"paper", "exact", "regularized"})
                    for (int k = 1; k <= 3; ++k) {
                        WorkPrecisionRow r;
                        r.caseId = c;
                        r.solver = s;
                        r.error = std::pow(10.0, -2.0 * k);
                        r.timing.minSeconds = 1e-4 * k;
                        study.rows.push_back(r);
                    }
            numerics->showStudy(study);
            QTest::qWait(100);
            const QRectF plot = page->findChild<QChartView*>()->chart()->plotArea();
            if (plot.height() < 120)
                problems << QStringLiteral("the work-precision plot %1 px tall").arg(plot.height());
        }
        // Scrolling down is fine where the content is taller than the tab; sideways it is not.
        if (auto* scroll = qobject_cast<QScrollArea*>(page);
            scroll && scroll->horizontalScrollBar()->isVisible())
            problems << QStringLiteral("the tab scrolls sideways: %1 px wide content in %2 px")
                            .arg(scroll->widget()->minimumSizeHint().width())
                            .arg(scroll->viewport()->width());
        for (QChartView* v : page->findChildren<QChartView*>())
            if (v->isVisible() && v->height() < 200)
                problems << QStringLiteral("a chart %1 px tall").arg(v->height());
        for (QTableWidget* t : page->findChildren<QTableWidget*>())
            if (t->isVisible() &&
                t->viewport()->height() < 3 * t->verticalHeader()->defaultSectionSize())
                problems << QStringLiteral("a table with room for %1 px of rows")
                                .arg(t->viewport()->height());
        for (QAbstractButton* b : page->findChildren<QAbstractButton*>())
            if (b->isVisible() && !qobject_cast<QToolButton*>(b->parentWidget()) &&
                (b->width() < b->minimumSizeHint().width() ||
                 b->height() < b->minimumSizeHint().height()))
                problems << QStringLiteral("\"%1\" %2×%3")
                                .arg(b->text())
                                .arg(b->width())
                                .arg(b->height());
            else if (b->isVisible() && !shownRect(b).isEmpty() && shownRect(b).width() < b->width())
                problems << QStringLiteral("\"%1\" cut to %2 of %3 px")
                                .arg(b->text())
                                .arg(shownRect(b).width())
                                .arg(b->width());
        QVERIFY2(problems.isEmpty(), qPrintable(problems.join(QStringLiteral("; "))));
    }

    // Every project file shipped in resources/examples (a study spec is not one) is offered,
    // and opens from its copy with what it refers to beside it.
    void openExampleListsEveryProject() {
        const QDir dir(QStringLiteral(KINSTAB_SOURCE_DIR "/resources/examples"));
        QStringList shipped;
        for (const QString& name : dir.entryList({QStringLiteral("*.json")}, QDir::Files)) {
            QFile f(dir.filePath(name));
            QVERIFY(f.open(QIODevice::ReadOnly));
            if (QJsonDocument::fromJson(f.readAll()).object().value("format") ==
                QLatin1String("kinstab-project"))
                shipped << name;
        }
        QCOMPARE_GE(shipped.size(), 5);
        QStringList offered;
        for (const ExampleProject& e : exampleProjects())
            offered << QFileInfo(e.resource).fileName();
        for (const QString& name : shipped)
            QVERIFY2(offered.contains(name), qPrintable(name + " is not under Open example"));
        auto* menu = w->findChild<QMenu*>(QStringLiteral("exampleMenu"));
        QVERIFY(menu);
        QCOMPARE(menu->actions().size(), shipped.size());
        QTemporaryDir copies;
        for (const ExampleProject& e : exampleProjects()) {
            QString error;
            const QString path = copyExample(e, copies.path(), &error);
            QVERIFY2(!path.isEmpty(), qPrintable(error));
            QVERIFY2(w->openProject(path, true), qPrintable(path));
        }
        // The study example's spec and its six horizontal records came with it.
        QVERIFY(QFile::exists(copies.filePath(QStringLiteral("examples/study-example.json"))));
        QCOMPARE(QDir(copies.filePath(QStringLiteral("records")))
                     .entryList({QStringLiteral("*.AT2")}, QDir::Files)
                     .size(),
                 6);
    }

    void saveAsHasAShortcut() {
        auto* a = w->findChild<QAction*>(QStringLiteral("saveAsAction"));
        QVERIFY(a);
        QVERIFY(!a->shortcut().isEmpty());
    }
};

int main(int argc, char** argv) {
    // One 1280 × 800 screen with window frames, whatever QT_QPA_PLATFORM the caller set.
    QTemporaryDir config;
    const QString file = config.filePath(QStringLiteral("screen.json"));
    QFile f(file);
    if (!f.open(QIODevice::WriteOnly)) return 1;
    f.write(R"({"windowFrameMargins": true, "screens": [{"name": "laptop", "x": 0, "y": 0,
        "width": 1280, "height": 800, "logicalDpi": 96, "logicalBaseDpi": 96, "dpr": 1}]})");
    f.close();
    qputenv("QT_QPA_PLATFORM", "offscreen:configfile=" + file.toLocal8Bit());
    QApplication app(argc, argv);
    TstScreen1280 test;
    QTEST_SET_MAIN_SOURCE_PATH
    return QTest::qExec(&test, argc, argv);
}

#include "tst_screen_1280.moc"
