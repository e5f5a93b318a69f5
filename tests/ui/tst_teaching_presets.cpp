// SPDX-License-Identifier: GPL-3.0-or-later
// One-click presets for the paper's figures and the sliders that re-run (issue #9).
// Expected settings are the paper's captions (Furgerson 1980, list of figures, Figs. 28-35):
// Figs. 28-30 gamma_c = tau_max / tau_c and Figs. 31-33 tau_rise / tau_c for the fast,
// moderately and slowly rising envelopes over 0.7 <= A <= 1.15, 0.5 <= f <= 1.125 (ch. IV,
// Results); Fig. 34 tau_c against A at f = 0.75 Hz, moderate; Fig. 35 A = 1.0, f = 1.125 Hz,
// moderate; Figs. 37-42 planar, moderate, A_y = 0.9 A_x, f_y as listed. All at t* = 0.099 s
// (Table 4), mu = 0.6, bearing d/2.

#include "core/slab/Slab1DCase.h"
#include "ui/teaching/ParameterPanel.h"
#include "ui/teaching/SurfaceMarker.h"
#include "ui/teaching/TeachingPlayer.h"
#include "ui/teaching/TeachingView.h"

#include <QDoubleSpinBox>
#include <QSignalSpy>
#include <QSlider>
#include <QtTest>

#include <cmath>

using namespace kinstab;
using namespace kinstab::ui;

class TestTeachingPresets : public QObject {
    Q_OBJECT
private slots:
    void presetSetsPaperParameters_data() {
        QTest::addColumn<QString>("id");
        QTest::addColumn<int>("envelope");
        QTest::addColumn<int>("scale");
        QTest::addColumn<double>("amplitude");
        QTest::addColumn<double>("frequency");
        QTest::addColumn<int>("mode");
        const int fast = int(EnvelopePreset::Fast), mod = int(EnvelopePreset::Moderate),
                  slow = int(EnvelopePreset::Slow);
        const int tmax = int(TauScale::TauMax), trise = int(TauScale::TauRise);
        const int surf = int(MapMode::Surface);
        QTest::newRow("Fig. 28 fast, tau_max") << "fig28" << fast << tmax << 1.0 << 1.0 << surf;
        QTest::newRow("Fig. 29 moderate, tau_max") << "fig29" << mod << tmax << 1.0 << 1.0 << surf;
        QTest::newRow("Fig. 30 slow, tau_max") << "fig30" << slow << tmax << 1.0 << 1.0 << surf;
        QTest::newRow("Fig. 31 fast, tau_rise") << "fig31" << fast << trise << 1.0 << 1.0 << surf;
        QTest::newRow("Fig. 32 moderate, tau_rise")
            << "fig32" << mod << trise << 1.0 << 1.0 << surf;
        QTest::newRow("Fig. 33 slow, tau_rise") << "fig33" << slow << trise << 1.0 << 1.0 << surf;
        QTest::newRow("Fig. 34 tau_c vs A at f=0.75")
            << "fig34" << mod << tmax << 1.0 << 0.75 << int(MapMode::Slice);
        QTest::newRow("Fig. 35 A=1.0 f=1.125") << "fig35" << mod << tmax << 1.0 << 1.125 << surf;
    }

    void planarPresets_data() {
        QTest::addColumn<QString>("id");
        QTest::addColumn<double>("fy");
        // Ch. VI list of figures: f_y = 0.2, 0.5, 1.0, 2.0, 5.0, 10.0 Hz for Figs. 37-42.
        QTest::newRow("Fig. 37 f_y=0.2") << "fig37" << 0.2;
        QTest::newRow("Fig. 38 f_y=0.5") << "fig38" << 0.5;
        QTest::newRow("Fig. 39 f_y=1.0") << "fig39" << 1.0;
        QTest::newRow("Fig. 40 f_y=2.0") << "fig40" << 2.0;
        QTest::newRow("Fig. 41 f_y=5.0") << "fig41" << 5.0;
        QTest::newRow("Fig. 42 f_y=10.0") << "fig42" << 10.0;
    }

    void planarPresets() {
        QFETCH(QString, id);
        QFETCH(double, fy);
        TeachingView view;
        QVERIFY(view.applyPreset(id));
        const TeachingParams p = view.params();
        QCOMPARE(int(p.model), int(TeachingModel::Planar));
        QCOMPARE(int(p.envelope), int(EnvelopePreset::Moderate));
        QCOMPARE(int(p.scale), int(TauScale::TauMax));
        QCOMPARE(p.fyHz, fy);
        QCOMPARE(p.ayRatio, 0.9); // ch. VI: A_y = 0.9 A_x
        QCOMPARE(p.theta, 20.0);  // ch. VI: Theta = 2 wall length / wall width
        QCOMPARE(p.mu, 0.6);
        QCOMPARE(view.mapRange(), kPlanarRange); // ch. VI: A_x 0.5..1.15, f_x 0.5..2.0
        QCOMPARE(view.parameterPanel()->params(), p);
        // The run shown is the planar solver's (independent call).
        PlanarEventLog directEvents;
        const PlanarResult direct =
            runPlanar(p.toPlanarCase(), p.amplitude, p.frequencyHz, &directEvents);
        QCOMPARE(view.run().result().outcome, direct.slab.outcome);
        QCOMPARE(view.run().events().size(), directEvents.events.size());
        QCOMPARE(view.run().exitSide(), direct.exitSide);
    }

    void presetSetsPaperParameters() {
        QFETCH(QString, id);
        QFETCH(int, envelope);
        QFETCH(int, scale);
        QFETCH(double, amplitude);
        QFETCH(double, frequency);
        QFETCH(int, mode);
        TeachingView view;
        view.setParams(
            TeachingParams{EnvelopePreset::Fast, TauScale::One, 0.3, 3.0, 0.2, 0.3, 0.5});
        QSignalSpy applied(&view, &TeachingView::presetApplied);
        QVERIFY(view.applyPreset(id));
        QCOMPARE(applied.count(), 1);
        QCOMPARE(view.currentPresetId(), id);
        const TeachingParams p = view.params();
        QCOMPARE(int(p.envelope), envelope);
        QCOMPARE(int(p.scale), scale);
        QCOMPARE(p.amplitude, amplitude);
        QCOMPARE(p.frequencyHz, frequency);
        QCOMPARE(p.mu, 0.6);
        QCOMPARE(p.limit, 1.0);
        QCOMPARE_LE(std::abs(view.run().tstar() - 0.099), 1e-15);
        QCOMPARE(int(view.mapMode()), mode);
        QCOMPARE(view.mapRange(), kPaperRange);
        QCOMPARE(view.player()->tau(), 0.0);
        // The panel shows the preset and hands back the exact values (no rounding of d).
        QCOMPARE(view.parameterPanel()->params(), p);
        QCOMPARE(view.parameterPanel()->spinBox(ParameterPanel::Quantity::Frequency)->value(),
                 frequency);
        // The run shown is the solver's for these settings.
        SlabEventLog directEvents;
        const SlabResult direct = runSlab1D(p.toCase(), amplitude, frequency, {}, &directEvents);
        QCOMPARE(view.run().result().outcome, direct.outcome);
        QCOMPARE(view.run().events().size(), directEvents.events.size());
    }

    void unknownPresetIsRefused() {
        TeachingView view;
        const TeachingParams before = view.params();
        QVERIFY(!view.applyPreset(QStringLiteral("fig99")));
        QCOMPARE(view.params(), before);
    }

    void fig29PointCollapsesAtPaperCritical() {
        // Ch. V: for f = 1 Hz on Fig. 29's surface the largest safe A is 0.95; docs/theory.md
        // §4: 1.00 collapses.
        TeachingView view;
        QVERIFY(view.applyPreset(QStringLiteral("fig29")));
        QCOMPARE(view.run().result().outcome, Outcome::Collapsed);
        QCOMPARE_LE(std::abs(view.run().gammaC() - 37.89 / view.run().result().tauC),
                    1e-12); // Table 4 tau_max
    }

    void surfaceMapMatchesSolver() {
        // The "where am I" map is the solver's gamma_c on the grid (independent direct runs).
        TeachingView view;
        QVERIFY(view.applyPreset(QStringLiteral("fig32")));
        SurfaceMarker* m = view.surfaceMarker();
        QTRY_VERIFY_WITH_TIMEOUT(m->hasMap() && !m->isComputing(), 60000);
        const MarkerMap& map = m->map();
        QCOMPARE(map.sweep.grid.amplitudes.size(), std::size_t(SurfaceMarker::kCells));
        QCOMPARE(map.sweep.grid.amplitudes.front(), kPaperRange.aMin);
        QCOMPARE(map.sweep.grid.frequencies.back(), kPaperRange.fMax);
        const Slab1DCase c = view.params().toCase();
        for (std::size_t i : {0, 11, 23})
            for (std::size_t j : {0, 12, 23}) {
                const double a = map.sweep.grid.amplitudes[i], f = map.sweep.grid.frequencies[j];
                const double want = collapseFactor(c.tauRef(), runSlab1D(c, a, f));
                QCOMPARE(map.gamma[i * map.sweep.grid.frequencies.size() + j], want);
            }
        QCOMPARE(map.tauRef, 8.92); // Table 4: tau_rise of the moderate envelope
    }

    void fig34SliceIsAtFixedFrequency() {
        TeachingView view;
        QVERIFY(view.applyPreset(QStringLiteral("fig34")));
        SurfaceMarker* m = view.surfaceMarker();
        QTRY_VERIFY_WITH_TIMEOUT(m->hasMap() && !m->isComputing(), 60000);
        QCOMPARE(m->map().sweep.grid.frequencies.size(), std::size_t(1));
        QCOMPARE(m->map().sweep.grid.frequencies[0], 0.75);
        QCOMPARE(m->map().sweep.grid.amplitudes.size(), std::size_t(SurfaceMarker::kSlicePoints));
    }

    void slidersRerun_data() {
        QTest::addColumn<int>("quantity");
        QTest::addColumn<int>("sliderValue");
        QTest::addColumn<double>("value");
        using Q = ParameterPanel::Quantity;
        // A steps of 0.005 g: 190 -> 0.95 g (docs/theory.md §4: stable at f = 1 Hz), 200 -> 1.00
        // (collapses).
        QTest::newRow("A slider to 0.95 g") << int(Q::Amplitude) << 190 << 0.95;
        QTest::newRow("A slider to 1.00 g") << int(Q::Amplitude) << 200 << 1.00;
        QTest::newRow("f slider to 0.75 Hz") << int(Q::Frequency) << 150 << 0.75;
        QTest::newRow("mu slider to 0.45") << int(Q::Mu) << 45 << 0.45;
        QTest::newRow("wall slider to 100 mm") << int(Q::WallWidth) << 200 << 100.0;
    }

    void slidersRerun() {
        QFETCH(int, quantity);
        QFETCH(int, sliderValue);
        QFETCH(double, value);
        TeachingView view;
        QVERIFY(view.applyPreset(QStringLiteral("fig29")));
        TeachingParams start = view.params();
        start.amplitude = 0.5; // so that every row moves its slider
        view.setParams(start);
        QSignalSpy reran(&view, &TeachingView::runChanged);
        QSlider* s = view.parameterPanel()->slider(static_cast<ParameterPanel::Quantity>(quantity));
        s->setValue(sliderValue);
        QCOMPARE(reran.count(), 1);
        const TeachingParams p = view.params();
        switch (static_cast<ParameterPanel::Quantity>(quantity)) {
        case ParameterPanel::Quantity::Amplitude:
            QCOMPARE(p.amplitude, value);
            break;
        case ParameterPanel::Quantity::Frequency:
            QCOMPARE(p.frequencyHz, value);
            break;
        case ParameterPanel::Quantity::Mu:
            QCOMPARE(p.mu, value);
            break;
        case ParameterPanel::Quantity::WallWidth:
            QCOMPARE(p.wallWidthM, value / 1000.0);
            QCOMPARE_LE(std::abs(view.run().tstar() - std::sqrt(0.1 / (2 * 9.80665))),
                        1e-15); // docs/theory.md §2
            break;
        }
        QVERIFY(view.currentPresetId().isEmpty()); // no longer the figure's settings
        SlabEventLog directEvents;
        const SlabResult direct =
            runSlab1D(p.toCase(), p.amplitude, p.frequencyHz, {}, &directEvents);
        QCOMPARE(view.run().result().outcome, direct.outcome);
        QCOMPARE(view.run().events().size(), directEvents.events.size());
        if (quantity == int(ParameterPanel::Quantity::Amplitude))
            QCOMPARE(view.run().result().outcome,
                     value < 0.96 ? Outcome::Stable : Outcome::Collapsed);
    }

    void badInputIsReportedNotRun() {
        TeachingView view;
        TeachingParams p = view.params();
        p.amplitude = std::nan("");
        view.setParams(p);
        QVERIFY(!view.run().error().empty());
        QVERIFY(QString::fromStdString(view.run().error()).contains(QStringLiteral("amplitude")));
        QCOMPARE(view.run().events().size(), std::size_t(0));
        view.player()->play();
        view.player()->advance(1.0);
        QVERIFY(view.player()->atEnd());
    }
};

QTEST_MAIN(TestTeachingPresets)
#include "tst_teaching_presets.moc"
