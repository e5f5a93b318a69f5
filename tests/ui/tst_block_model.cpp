// SPDX-License-Identifier: GPL-3.0-or-later
// The GUI's "free-standing block" model (issue 32), offscreen: choosing it shows the block's
// fields and the overturning map view; Run computes a map whose every point agrees with core's
// overturningMap called here for the same inputs (the other equations' map too); Cancel stops
// it; a bad b is refused beside its field and nothing runs; the choice and its inputs survive
// save and open, and a project from before the block model opens with the slab model and saves
// without a "block_map" key.

#include "WindowFields.h"
#include "core/base/UnitSystem.h"
#include "core/rocking/OverturningMap.h"
#include "ui/BackgroundJob.h"
#include "ui/BlockMapView.h"
#include "ui/HelpMenu.h"
#include "ui/MainWindow.h"
#include "ui/ModelPanel.h"
#include "ui/NumberField.h"
#include "ui/OverturningMapPlot.h"
#include "ui/StaleFrame.h"

#include <QAction>
#include <QComboBox>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTest>

#include <memory>

using namespace kinstab;
using namespace kinstab::ui;

class TestBlockModel : public QObject {
    Q_OBJECT
private:
    std::unique_ptr<MainWindow> w;
    NumberField* field(const char* name) { return testing::namedField(w.get(), name); }
    QComboBox* combo(const char* name) {
        return w->modelPanel()->findChild<QComboBox*>(QString::fromLatin1(name));
    }
    void type(const char* name, const QString& text) {
        QLineEdit* e = field(name)->lineEdit();
        e->selectAll();
        QTest::keyClicks(e, text); // typed, as a user would
    }
    // A length typed in the unit the field shows (the paper's example opens in ft).
    double metresPerShown() const { return metresPerUnit(w->unitSystem(), LengthScale::Structure); }
    bool waitMap(int ms) {
        QSignalSpy spy(w.get(), &MainWindow::blockMapFinished);
        return spy.wait(ms);
    }
    void chooseBlock() {
        combo("model")->setCurrentIndex(2);
        QVERIFY(w->modelPanel()->isBlock());
    }

private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QSettings().clear(); // a first start: the paper's example
    }
    void init() {
        w = std::make_unique<MainWindow>();
        w->show();
        QVERIFY(QTest::qWaitForWindowExposed(w.get()));
    }
    void cleanup() { w.reset(); }

    void choosingTheBlockShowsItsFieldsAndMap() {
        QVERIFY(!field("blockHalfWidth")->isVisibleTo(w.get()));
        chooseBlock();
        for (const char* f : {"blockHalfWidth", "blockHalfHeight", "blockMu", "blockRestitution",
                              "mapAmplitudeMax", "mapFrequencyMax", "mapPoints"})
            QVERIFY2(field(f)->isVisibleTo(w.get()), f);
        QVERIFY(!field("fy")->isVisibleTo(w.get()));
        QVERIFY(w->blockMapView()->isVisibleTo(w.get()));
        auto* tabs = w->findChild<QTabWidget*>();
        QCOMPARE(tabs->tabText(0), QStringLiteral("Overturning map"));
        // F1 on the map opens the guide where the block model is told (docs/user-guide.md).
        QCOMPARE(helpSectionFor(w->blockMapView()), QStringLiteral("Model"));
        // The project's slab model is unchanged: the block map is no slab model.
        QVERIFY(w->project().model == ModelKind::Slab1D);
        QVERIFY(w->project().blockMap.selected);
        combo("model")->setCurrentIndex(0);
        QCOMPARE(tabs->tabText(0), QStringLiteral("γc surface"));
        QVERIFY(!field("blockHalfWidth")->isVisibleTo(w.get()));
    }

    // b = 0.5, h = 1.5 in the unit shown, restitution 0.9, one-sine, exact, no sliding, a 9 x 9
    // map to 9 a_p/(alpha g) and 9 omega_p/p: every point as core's overturningMap computes it
    // for the same block (the independent reference: core called here, its model and spec built
    // without the GUI's helpers).
    void mapAgreesWithCore() {
        chooseBlock();
        type("blockHalfWidth", QStringLiteral("0.5"));
        type("blockHalfHeight", QStringLiteral("1.5"));
        type("blockRestitution", QStringLiteral("0.9"));
        type("mapAmplitudeMax", QStringLiteral("9"));
        type("mapFrequencyMax", QStringLiteral("9"));
        type("mapPoints", QStringLiteral("9"));
        combo("blockPulse")->setCurrentIndex(1); // one-sine
        QVERIFY(w->runAction()->isEnabled());
        w->runAction()->trigger();
        // (Not isRunning(): the 162 runs of this map can end on the worker before this line;
        // the actions change only when the result is delivered on this thread.)
        QVERIFY(!w->runAction()->isEnabled());
        QVERIFY(w->cancelAction()->isEnabled());
        QVERIFY(waitMap(120000));
        const auto& result = w->blockMapView()->result();
        QVERIFY(result.has_value());
        QVERIFY(result->other.has_value());

        RockingModel m;
        m.block = {0.5 * metresPerShown(), 1.5 * metresPerShown()};
        m.restitution = 0.9;
        m.equations = RockingEquations::Exact;
        OverturningMapSpec spec;
        spec.shape = PulseShape::OneSine;
        spec.amplitudeMin = spec.frequencyMin = 1.0; // one step of 9 / 9 above 0
        spec.amplitudeMax = spec.frequencyMax = 9.0;
        spec.amplitudePoints = spec.frequencyPoints = 9;
        const OverturningMap exact = overturningMap(m, spec);
        m.equations = RockingEquations::Linearised;
        const OverturningMap linear = overturningMap(m, spec);
        QCOMPARE(result->main.amplitudes, exact.amplitudes);
        QCOMPARE(result->main.frequencies, exact.frequencies);
        QCOMPARE(result->main.overturns, exact.overturns);
        QCOMPARE(result->main.maxThetaOverAlpha, exact.maxThetaOverAlpha);
        QCOMPARE(result->other->overturns, linear.overturns);
        QCOMPARE(result->other->maxThetaOverAlpha, linear.maxThetaOverAlpha);
        int over = 0;
        for (unsigned char o : exact.overturns)
            over += o == 1;
        QVERIFY(over > 0 && over < 81); // both fates on the map: the test can tell them apart
        QVERIFY(!w->blockMapView()->isStale());

        // Hovering a point reads it out: the centre of point (i, j) = (4, 8).
        OverturningMapPlot* plot = w->blockMapView()->plot();
        const QRectF r = plot->plotRect();
        const QPoint at(static_cast<int>(r.left() + r.width() * 4.5 / 9),
                        static_cast<int>(r.bottom() - r.height() * 8.5 / 9));
        QTest::mouseMove(plot, at);
        QTRY_VERIFY(!w->blockMapView()->readoutText().isEmpty());
        const QString text = w->blockMapView()->readoutText();
        QVERIFY2(text.startsWith(QStringLiteral("ω_p/p = 5.000, a_p/(αg) = 9.000")),
                 qPrintable(text));
        const std::size_t k = exact.at(4, 8);
        const QString fate = exact.overturns[k] == 1
                                 ? QStringLiteral("overturns (exact)")
                                 : QStringLiteral("survives, max |θ|/α = %1 (exact)")
                                       .arg(exact.maxThetaOverAlpha[k], 0, 'f', 3);
        QVERIFY2(text.contains(fate), qPrintable(text + " / " + fate));

        // An input change dims the map, as it dims the γc surface.
        type("blockHalfWidth", QStringLiteral("0.4"));
        QVERIFY(w->blockMapView()->isStale());
        QVERIFY(w->blockMapView()->findChild<StaleFrame*>()->isStale());
        type("blockHalfWidth", QStringLiteral("0.5"));
        QVERIFY(!w->blockMapView()->isStale());
    }

    void cancelStopsTheMap() {
        chooseBlock();
        type("mapPoints", QStringLiteral("1001")); // 2 million runs: minutes, unless cancelled
        w->runAction()->trigger();
        QVERIFY(w->blockMapView()->isRunning());
        QVERIFY(!w->runAction()->isEnabled());
        QSignalSpy spy(w.get(), &MainWindow::blockMapFinished);
        w->cancelAction()->trigger();
        QVERIFY(spy.count() > 0 || spy.wait(30000));
        QVERIFY(!w->blockMapView()->isRunning());
        QVERIFY(!w->blockMapView()->result().has_value()); // nothing half-computed is shown
        QVERIFY(w->runAction()->isEnabled());
    }

    void badHalfWidthIsRefusedBesideTheField() {
        chooseBlock();
        type("blockHalfWidth", QStringLiteral("-1"));
        NumberField* b = field("blockHalfWidth");
        QVERIFY(!b->isValid());
        QVERIFY(b->error().contains(QStringLiteral("-1")));
        bool shown = false;
        for (QLabel* l : b->findChildren<QLabel*>())
            shown |= l->isVisibleTo(w.get()) && l->text() == b->error();
        QVERIFY2(shown, qPrintable(b->error()));
        QVERIFY(!w->runAction()->isEnabled());
        QVERIFY(w->runAction()->toolTip().contains(QStringLiteral("Half-")));
        w->runSweep(); // even when asked directly, nothing runs
        QVERIFY(!w->blockMapView()->isRunning());
        QVERIFY(!w->blockMapView()->result().has_value());
    }

    void choiceSurvivesSaveAndOpen() {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("block.json"));
        chooseBlock();
        type("blockHalfWidth", QStringLiteral("0.25"));
        type("blockMu", QStringLiteral("0.7"));
        type("blockRestitution", QStringLiteral("0.85"));
        combo("blockEquations")->setCurrentIndex(1); // linearised
        combo("blockPulse")->setCurrentIndex(3);     // rectangular
        type("mapPoints", QStringLiteral("33"));
        const BlockMapSettings before = w->project().blockMap;
        QVERIFY(before.selected);
        QCOMPARE(before.shape, PulseShape::Rectangular);
        QCOMPARE(before.equations, RockingEquations::Linearised);
        QCOMPARE(before.points, 33);
        QCOMPARE_LE(std::abs(before.block.halfWidth - 0.25 * metresPerShown()), 1e-12);
        QCOMPARE(*before.mu, 0.7);
        QCOMPARE(w->saveProjectAs(path), QString());
        w->newProject();
        QVERIFY(!w->modelPanel()->isBlock());
        QVERIFY(w->openProject(path, true));
        QVERIFY(w->modelPanel()->isBlock());
        QCOMPARE(combo("blockPulse")->currentIndex(), 3);
        QCOMPARE(combo("blockEquations")->currentIndex(), 1);
        QVERIFY(w->project().blockMap == before);
        // Stored in metres whatever the unit shown.
        QFile f(path);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QByteArray text = f.readAll();
        QVERIFY(text.contains("\"block_map\""));
        QVERIFY(text.contains("\"pulse\": \"rectangular\""));
    }

    void oldProjectOpensWithTheSlab() {
        QTemporaryDir dir;
        const QString copy = dir.filePath(QStringLiteral("old.json"));
        QVERIFY(QFile::copy(
            QStringLiteral(KINSTAB_SOURCE_DIR "/resources/examples/paper-16-story.json"), copy));
        QVERIFY(w->openProject(copy, true));
        QVERIFY(!w->modelPanel()->isBlock());
        QVERIFY(w->project().blockMap == BlockMapSettings{});
        const QString saved = dir.filePath(QStringLiteral("saved.json"));
        QCOMPARE(w->saveProjectAs(saved), QString());
        QFile f(saved);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QVERIFY(!f.readAll().contains("block_map")); // a file without the block stays so
    }
};

QTEST_MAIN(TestBlockModel)
#include "tst_block_model.moc"
