// SPDX-License-Identifier: GPL-3.0-or-later
// The desktop window, offscreen (2D heat map instead of the 3D surface): input checks gate
// Run, a cancelled sweep keeps its points, a finished sweep shows exactly what runSweep (and
// kinstab-cli surface) computes, and picking a point shows that point's history.

#include "WindowFields.h"
#include "core/io/Project.h"
#include "core/sweep/Sweep.h"
#include "ui/BuildingPanel.h"
#include "ui/CodesPanel.h"
#include "ui/ExcitationPanel.h"
#include "ui/GridPanel.h"
#include "ui/HistoryChart.h"
#include "ui/MainWindow.h"
#include "ui/NumberField.h"
#include "ui/SlabPanel.h"
#include "ui/SurfaceView.h"
#include "ui/VerdictPanel.h"

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QGroupBox>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QLineEdit>
#include <QProcess>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <ctime>
#include <memory>
#include <thread>

using namespace kinstab;
using namespace kinstab::ui;

class TestMainWindow : public QObject {
    Q_OBJECT
private:
    std::unique_ptr<MainWindow> w;
    NumberField* field(const char* name) { return testing::namedField(w.get(), name); }
    void setText(const char* name, const QString& text) {
        QLineEdit* e = field(name)->lineEdit();
        e->selectAll();
        QTest::keyClicks(e, text); // typed, as a user would
        if (e->text() != text) e->setText(text);
    }
    // A grid small enough for a test, on the paper's critical region (Figs. 28-34).
    void smallGrid() {
        GridRanges r{0.9, 1.1, 0.05, 0.5, 1.25, 0.25};
        w->gridPanel()->setRanges(r);
    }
    bool waitFinished(int ms) {
        QSignalSpy spy(w.get(), &MainWindow::sweepFinished);
        return spy.count() > 0 || spy.wait(ms);
    }

private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QSettings().clear(); // a first start
    }
    void init() {
        w = std::make_unique<MainWindow>();
        w->show();
        QVERIFY(QTest::qWaitForWindowExposed(w.get()));
    }
    void cleanup() { w.reset(); }

    // First start: the paper's 16-story example (Furgerson 1980 ch. V) is open.
    void firstStartShowsPaperExample() {
        const Project p = w->project();
        QCOMPARE(p.building.stories, 16);
        QCOMPARE(p.building.height, 177.0);
        QCOMPARE(p.building.planDimension, 78.62);
        QVERIFY(p.codes.ubc1976.has_value());
        QVERIFY(p.codes.atc306.has_value());
        QCOMPARE(w->verdictPanel()->rowCount(), 4); // UBC 1976, ATC 3-06, ASCE 7-22, EC8
    }

    // The paper's verdict (ch. V): A_crit(1 Hz) = 0.95 against F16/w = 0.140 (UBC 1976) and
    // 0.275 (ATC 3-06): overstress governs. docs/theory.md §4: A = 0.95 is stable, A = 1.00
    // collapses.
    void paperExampleVerdict() {
        smallGrid();
        QSignalSpy assessed(w.get(), &MainWindow::assessmentFinished);
        w->runAction()->trigger();
        QVERIFY(waitFinished(120000));
        // The run's own checks first, said to be so, then the project's whole assessment.
        // (The run's end and the assessment's start are separate events: the note says either
        // that it is being assessed or that these are the run's checks, never "Governing".)
        if (assessed.isEmpty()) {
            if (!w->fullAssessment())
                QVERIFY(!w->verdictPanel()->governingText().startsWith("Governing"));
            QVERIFY(assessed.wait(120000));
        }
        QCOMPARE(w->verdictPanel()->rowCount(), 4);
        for (int row = 0; row < 2; ++row)
            QCOMPARE(w->verdictPanel()->verdictText(row), QStringLiteral("overstress governs"));
        // The assessment's sine checks, governed by ATC 3-06's (the largest ratio, 0.275).
        QCOMPARE(w->verdictPanel()->basisText(0), QStringLiteral("sine"));
        QCOMPARE(w->verdictPanel()->checkText(1), QStringLiteral("sine.atc306"));
        QVERIFY2(w->verdictPanel()->governingText().startsWith("Governing: sine.atc306"),
                 qPrintable(w->verdictPanel()->governingText()));
        const auto& codes = w->surfaceView()->overlays().codes;
        QCOMPARE(codes.size(), std::size_t(4));
        QVERIFY(w->lastCheck().has_value());
        const CodeVerdict& ubc = w->lastCheck()->codes.front();
        QVERIFY(ubc.aCrit.has_value());
        QVERIFY(*ubc.aCrit > 0.95 && *ubc.aCrit <= 1.0);
        QCOMPARE(ubc.frequencyHz, 1.0);
    }

    void saveThenOpenReproducesEveryInput() {
        // Change inputs on every panel, away from the example's values.
        setText("stories", "12");
        // Lengths in SI (m, wall width in mm); the file keeps the building's feet.
        w->findChild<QAction*>(QStringLiteral("unitsSI"))->trigger();
        setText("height", "120.5");
        setText("planDimension", "60");
        setText("period", "0.8");
        setText("mu", "0.55");
        w->slabPanel()->findChild<QComboBox*>()->setCurrentIndex(0); // by wall width
        setText("wallWidth", "250");
        setText("limit", "1.25");
        setText("ubc76K", "1.0");
        setText("atcAa", "0.3");
        for (QGroupBox* g : w->codesPanel()->findChildren<QGroupBox*>())
            if (g->title().startsWith("UBC 1997")) g->setChecked(true);
        setText("ubc97R", "5.5");
        w->excitationPanel()->setEnvelope(Envelope{0.2, 0.9, std::nullopt});
        w->excitationPanel()->setScale(TauScale::TauRise);
        w->gridPanel()->setRanges(GridRanges{0.5, 1.3, 0.1, 0.4, 2.0, 0.2});
        QVERIFY(w->inputsValid());
        const nlohmann::json before = projectToJson(w->project());

        QTemporaryDir dir;
        const QString path = dir.filePath("p.json");
        QCOMPARE(w->saveProjectAs(path), QString());
        w->newProject();
        QVERIFY(projectToJson(w->project()) != before);
        QVERIFY(w->openProject(path, true));
        QCOMPARE(QString::fromStdString(projectToJson(w->project()).dump(1)),
                 QString::fromStdString(before.dump(1)));
        QCOMPARE(w->projectPath(), path);
        // A broken file is refused with the window unchanged.
        QFile broken(dir.filePath("broken.json"));
        QVERIFY(broken.open(QIODevice::WriteOnly));
        broken.write(
            "{\"format\": \"kinstab-project\", \"version\": 1, \"building\": {\"height\": -3");
        broken.close();
        QVERIFY(!w->openProject(broken.fileName(), true));
        QCOMPARE(QString::fromStdString(projectToJson(w->project()).dump(1)),
                 QString::fromStdString(before.dump(1)));
    }

    void invalidValueDisablesRun_data() {
        QTest::addColumn<QString>("name");
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("reason");
        QTest::newRow("negative mu") << "mu"
                                     << "-0.2"
                                     << "must be ≥ 0.01 "; // kMuInput (core/slab/SlabInputs.h)
        QTest::newRow("mu not a number") << "mu"
                                         << "abc"
                                         << "is not a number";
        QTest::newRow("zero t*") << "tstar"
                                 << "0"
                                 << "must be ≥ 0.001";
        QTest::newRow("empty bearing") << "limit"
                                       << ""
                                       << "required";
        QTest::newRow("A step zero") << "aStep"
                                     << "0"
                                     << "must be > 0";
        QTest::newRow("A to below A from") << "aTo"
                                           << "0.1"
                                           << "must be ≥ A from";
        QTest::newRow("f from zero") << "fFrom"
                                     << "0"
                                     << "must be ≥ 0.001"; // kMinFrequencyHz
        QTest::newRow("negative height") << "height"
                                         << "-3"
                                         << "must be >";
        QTest::newRow("fractional stories") << "stories"
                                            << "2.5"
                                            << "whole number";
        QTest::newRow("UBC K out of range") << "ubc76K"
                                            << "7"
                                            << "must be";
    }
    void invalidValueDisablesRun() {
        QFETCH(QString, name);
        QFETCH(QString, text);
        QFETCH(QString, reason);
        QVERIFY(w->runAction()->isEnabled());
        const QString before = field(name.toLatin1())->lineEdit()->text();
        setText(name.toLatin1(), text);
        QVERIFY(!w->runAction()->isEnabled());
        NumberField* f = field(name.toLatin1());
        QVERIFY2(f->error().contains(reason), qPrintable(f->error()));
        // The reason is shown beside the field.
        bool shown = false;
        for (QLabel* l : f->findChildren<QLabel*>())
            if (l->isVisible() && l->text() == f->error()) shown = true;
        QVERIFY(shown);
        setText(name.toLatin1(), before);
        QVERIFY(w->runAction()->isEnabled());
    }

    void completedSweepMatchesRunSweep() {
        smallGrid();
        w->runAction()->trigger();
        QVERIFY(waitFinished(60000));
        const SweepResult& r = w->lastSweep();
        QCOMPARE(r.completed, r.grid.size());
        // Independent: the same case straight through core.
        const Slab1DCase c = w->currentCase();
        const SweepResult ref = runSweep(w->gridPanel()->grid(), slab1DPoint(c), nullptr, 1);
        const GammaGrid& shown = w->surfaceView()->data();
        QCOMPARE(shown.gamma.size(), ref.points.size());
        const std::vector<double> g = collapseFactors(ref, c.tauRef());
        for (std::size_t k = 0; k < g.size(); ++k) {
            QCOMPARE(static_cast<int>(r.points[k].outcome),
                     static_cast<int>(ref.points[k].outcome));
            QCOMPARE_LE(std::abs(shown.gamma[k] - g[k]), 1e-12);
        }
        // Something collapses and something does not: the paper's critical ratio 0.95 at 1 Hz
        // lies inside this grid.
        QVERIFY(*std::max_element(g.begin(), g.end()) > 0);
        QVERIFY(*std::min_element(g.begin(), g.end()) == 0);
    }

    void completedSweepMatchesCli() {
        if (!QFileInfo::exists(QStringLiteral(KINSTAB_CLI))) QSKIP("kinstab-cli not built");
        smallGrid();
        w->runAction()->trigger();
        QVERIFY(waitFinished(60000));
        // The same case as the window's (the paper's example: moderate envelope, tau_max scale).
        const Slab1DCase c = w->currentCase();
        QCOMPARE(c.envelope.name(), std::string("moderate"));
        QProcess cli;
        cli.start(QStringLiteral(KINSTAB_CLI),
                  {"surface", "--amplitudes", "0.9:1.1:0.05", "--frequencies", "0.5:1.25:0.25",
                   "--tstar", QString::number(c.tstar, 'g', 17), "--mu",
                   QString::number(c.slab.mu, 'g', 17), "--limit",
                   QString::number(c.slab.limit, 'g', 17)});
        QVERIFY(cli.waitForFinished(60000));
        QCOMPARE(cli.exitCode(), 0);
        const QJsonObject j = QJsonDocument::fromJson(cli.readAllStandardOutput()).object();
        const QJsonArray gamma = j.value("gamma_c").toArray();
        const GammaGrid& shown = w->surfaceView()->data();
        QCOMPARE(static_cast<std::size_t>(gamma.size()), shown.amplitudes.size());
        for (std::size_t i = 0; i < shown.amplitudes.size(); ++i)
            for (std::size_t jf = 0; jf < shown.frequencies.size(); ++jf) {
                const double want = gamma[static_cast<qsizetype>(i)]
                                        .toArray()[static_cast<qsizetype>(jf)]
                                        .toDouble();
                QCOMPARE_LE(std::abs(shown.at(i, jf) - want), 1e-12);
            }
    }

    void cancelKeepsPartialResults() {
        // 18 291 points at 10-30 Hz, each hundreds of slips (kinstab-cli surface: 5.5 s on two
        // cores): far longer than the cancel below. (A grid at 0.25-3 Hz now ends in 0.5 s, before
        // the cancel.) Each cancel must stop every worker after the point it holds. The wall-clock
        // latency depends on what else the machine runs: it is printed, not asserted (timing
        // belongs to kinstab-cli bench, CONTRIBUTING.md).
        w->gridPanel()->setRanges(GridRanges{0.6, 1.5, 0.01, 10.0, 30.0, 0.1});
        qint64 best = 1 << 30;
        for (int attempt = 0; attempt < 3; ++attempt) {
            w->runAction()->trigger();
            QVERIFY(w->cancelAction()->isEnabled());
            QVERIFY(!w->runAction()->isEnabled());
            QTRY_VERIFY_WITH_TIMEOUT(w->runner()->snapshot().completed > 20, 20000);
            QTest::qWait(2 * SweepRunner::updateIntervalMs); // let the surface show some points
            QElapsedTimer t;
            t.start();
            w->cancelAction()->trigger();
            const std::size_t atCancel = w->runner()->snapshot().completed;
            w->runner()->waitForFinished();
            best = std::min(best, t.elapsed());
            QCOMPARE_LE(w->runner()->snapshot().completed - atCancel,
                        static_cast<std::size_t>(std::thread::hardware_concurrency()));
            QVERIFY(waitFinished(5000));
        }
        qInfo("cancel took %lld ms (best of 3)", best);

        const SweepResult& r = w->lastSweep();
        QVERIFY(r.completed > 0);
        QVERIFY(r.completed < r.grid.size());
        // Done points shown with their value, the rest as holes.
        const GammaGrid& shown = w->surfaceView()->data();
        std::size_t finite = 0;
        for (std::size_t k = 0; k < shown.gamma.size(); ++k) {
            QCOMPARE(std::isfinite(shown.gamma[k]), r.done[k] != 0);
            finite += std::isfinite(shown.gamma[k]);
        }
        QCOMPARE(finite, r.completed);
        // The window is usable: Run works again and completes.
        QVERIFY(w->runAction()->isEnabled());
        QVERIFY(!w->cancelAction()->isEnabled());
        smallGrid();
        w->runAction()->trigger();
        QVERIFY(waitFinished(60000));
        QCOMPARE(w->lastSweep().completed, w->lastSweep().grid.size());
    }

    void pickingShowsHistory() {
        smallGrid();
        w->runAction()->trigger();
        QVERIFY(waitFinished(60000));
        const SweepResult& r = w->lastSweep();
        for (std::size_t i = 0; i < r.grid.amplitudes.size(); ++i) {
            const int fi = 2; // f = 1.0 Hz
            w->surfaceView()->selectPoint(static_cast<int>(i), fi);
            QVERIFY(w->pickedRun().has_value());
            const PointRun& p = *w->pickedRun();
            QCOMPARE(p.amplitude, r.grid.amplitudes[i]);
            QCOMPARE(p.frequency, r.grid.frequencies[fi]);
            // The on-demand run agrees with the sweep's point.
            const PointResult& s = r.at(i, fi);
            QCOMPARE(static_cast<int>(p.result.outcome), static_cast<int>(s.outcome));
            QVERIFY(w->historyChart()->sampleCount() > 10);
            if (s.outcome == Outcome::Collapsed) {
                QCOMPARE_LE(std::abs(p.result.tauC - s.tauC), 1e-12 * s.tauC);
                // The history ends at the collapse, beyond the bearing limit.
                QCOMPARE(p.history.samples.back().tau, p.result.tauC);
                QCOMPARE_GE(std::abs(p.history.samples.back().delta), p.limit * (1 - 1e-9));
            }
        }
    }

    // The event loop is never held by our own code for more than 50 ms: the CPU time the GUI
    // thread spends between two ticks of a 5 ms timer stays under that. (Wall-clock gaps also
    // include time the OS gives to other processes; they are reported, not asserted.)
    void uiStaysResponsiveDuringSweep() {
        w->gridPanel()->setRanges(GridRanges{0.6, 1.5, 0.01, 0.25, 3.0, 0.05});
        QElapsedTimer clock;
        qint64 last = 0, worstWall = 0;
        double lastCpu = 0, worstCpu = 0;
        auto cpuMs = [] {
            timespec ts{};
            clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
            return 1e3 * static_cast<double>(ts.tv_sec) + 1e-6 * static_cast<double>(ts.tv_nsec);
        };
        QTimer tick;
        tick.setInterval(5);
        connect(&tick, &QTimer::timeout, this, [&] {
            const qint64 now = clock.elapsed();
            const double cpu = cpuMs();
            worstWall = std::max(worstWall, now - last);
            worstCpu = std::max(worstCpu, cpu - lastCpu);
            last = now;
            lastCpu = cpu;
        });
        w->runAction()->trigger();
        clock.start();
        lastCpu = cpuMs();
        tick.start();
        QVERIFY(waitFinished(120000));
        tick.stop();
        qInfo("%zu-point sweep: longest event-loop gap %lld ms wall clock, %.1f ms GUI-thread CPU",
              w->lastSweep().grid.size(), worstWall, worstCpu);
        QCOMPARE_LE(worstCpu, 50.0);
    }
};

QTEST_MAIN(TestMainWindow)
#include "tst_mainwindow.moc"
