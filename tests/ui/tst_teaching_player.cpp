// SPDX-License-Identifier: GPL-3.0-or-later
// The Teaching view plays a run in step with the solver (issue #9): driven by the player's
// clock deterministically (advance() with fixed real-time ticks, no waits), the state the
// drawing shows must be, at every tick, the state of the solver's last event, and the
// sequence of states met stepping event to event must equal the solver's event list.
// The expected events come from an independent runSlab1D call, not from the view.

#include "core/slab/Slab1DCase.h"
#include "ui/teaching/EventLog.h"
#include "ui/teaching/TeachingPlayer.h"
#include "ui/teaching/TeachingView.h"

#include <QSignalSpy>
#include <QtTest>

#include <algorithm>

using namespace kinstab;
using namespace kinstab::ui;

Q_DECLARE_METATYPE(kinstab::ui::TeachingParams)

namespace {

TeachingParams paperCase(double a, double f, EnvelopePreset e = EnvelopePreset::Moderate) {
    TeachingParams p;
    p.envelope = e;
    p.amplitude = a;
    p.frequencyHz = f;
    p.wallWidthM = wallWidthFromTstar(0.099);
    return p;
}

std::vector<SlabEvent> solverEvents(const TeachingParams& p) {
    if (p.model == TeachingModel::Slab1D) {
        SlabEventLog log;
        runSlab1D(p.toCase(), p.amplitude, p.frequencyHz, {}, &log);
        return log.events;
    }
    std::vector<SlabEvent> ev;
    PlanarEventLog log;
    runPlanar(p.toPlanarCase(), p.amplitude, p.frequencyHz, &log);
    for (const PlanarEvent& e : log.events)
        ev.push_back({e.tau, e.kind, e.dx, e.ux, 0});
    return ev;
}

TeachingParams planarCase(double a, double f, double fy) {
    TeachingParams p = paperCase(a, f);
    p.model = TeachingModel::Planar;
    p.fyHz = fy;
    return p;
}

DisplayState expectedAt(const std::vector<SlabEvent>& ev, double tau) {
    const auto it = std::upper_bound(ev.begin(), ev.end(), tau,
                                     [](double t, const SlabEvent& e) { return t < e.tau; });
    return it == ev.begin() ? DisplayState::AtRest : displayStateOf(std::prev(it)->kind);
}

} // namespace

class TestTeachingPlayer : public QObject {
    Q_OBJECT
private slots:
    void playToEnd_data() {
        QTest::addColumn<TeachingParams>("params");
        QTest::addColumn<double>("speed");
        QTest::addColumn<int>("outcome");
        // docs/theory.md §4 paper checks: moderate envelope, mu 0.6, t* 0.099, f = 1 Hz.
        QTest::newRow("SPEC4: A=1.00 f=1 collapses, 1x")
            << paperCase(1.00, 1.0) << 1.0 << int(Outcome::Collapsed);
        QTest::newRow("SPEC4: A=0.95 f=1 stable, 10x")
            << paperCase(0.95, 1.0) << 10.0 << int(Outcome::Stable);
        QTest::newRow("Fig35: A=1.0 f=1.125, 2x") << paperCase(1.0, 1.125) << 2.0 << -1;
        QTest::newRow("Fig. 39 planar A=1.0 f=1 f_y=1, 1x")
            << planarCase(1.0, 1.0, 1.0) << 1.0 << -1;
        QTest::newRow("fast envelope A=1.1 f=0.5, 0.1x")
            << paperCase(1.1, 0.5, EnvelopePreset::Fast) << 0.1 << -1;
    }

    void playToEnd() {
        QFETCH(TeachingParams, params);
        QFETCH(double, speed);
        QFETCH(int, outcome);
        const std::vector<SlabEvent> ev = solverEvents(params);
        QVERIFY(!ev.empty());
        TeachingView view;
        view.setParams(params);
        QCOMPARE(view.run().events().size(), ev.size());
        if (outcome >= 0) QCOMPARE(int(view.run().result().outcome), outcome);
        TeachingPlayer* player = view.player();
        player->rewind();
        player->setSpeed(speed);
        QList<int> passed;
        connect(player, &TeachingPlayer::eventsPassed, this, [&](int first, int last) {
            for (int i = first; i <= last; ++i)
                passed << i;
        });
        QSignalSpy finished(player, &TeachingPlayer::finished);
        player->play();
        // 60 ticks per second of real time, driven by hand: the timer never fires here.
        const double tick = 1.0 / 60.0;
        const long maxTicks =
            static_cast<long>(player->tauEnd() * view.run().tstar() / speed / tick) + 10;
        long ticks = 0;
        while (player->isPlaying() && ticks++ < maxTicks) {
            player->advance(tick);
            QCOMPARE(view.displayedState(), expectedAt(ev, player->tau()));
        }
        QVERIFY(player->atEnd());
        QCOMPARE(finished.count(), 1);
        QVERIFY(!player->isPlaying());
        // Every event reached exactly once, in order.
        QCOMPARE(passed.size(), static_cast<int>(ev.size()));
        for (int i = 0; i < passed.size(); ++i)
            QCOMPARE(passed[i], i);
        QCOMPARE(view.displayedState(), displayStateOf(ev.back().kind));
    }

    void stepThroughEvents_data() { playToEnd_data(); }

    void stepThroughEvents() {
        QFETCH(TeachingParams, params);
        const std::vector<SlabEvent> ev = solverEvents(params);
        TeachingView view;
        view.setParams(params);
        view.player()->rewind();
        QCOMPARE(view.displayedState(), DisplayState::AtRest);
        // The states met stepping event to event: one per distinct event time (events at the same
        // tau are one step; the last of them is what the drawing shows).
        std::vector<DisplayState> want, got;
        for (std::size_t i = 0; i < ev.size(); ++i)
            if (i + 1 == ev.size() || ev[i + 1].tau > ev[i].tau)
                want.push_back(displayStateOf(ev[i].kind));
        const int last = static_cast<int>(ev.size()) - 1;
        while (view.player()->eventIndex() < last && got.size() < ev.size()) {
            view.player()->stepToNextEvent();
            got.push_back(view.displayedState());
            QCOMPARE(view.eventLog()->logModel()->current(),
                     view.player()->eventIndex()); // highlighted
        }
        QCOMPARE(got.size(), want.size());
        for (std::size_t i = 0; i < want.size(); ++i)
            QCOMPARE(int(got[i]), int(want[i]));
    }

    void eventLogClickJumps() {
        TeachingView view;
        view.resize(1300, 850);
        view.show();
        view.setParams(paperCase(1.0, 1.0));
        const auto& ev = view.run().events();
        QVERIFY(ev.size() > 3);
        EventLog* log = view.eventLog();
        const QModelIndex idx = log->logModel()->index(2, 0);
        log->scrollTo(idx);
        QTest::mouseClick(log->viewport(), Qt::LeftButton, {}, log->visualRect(idx).center());
        QCOMPARE(view.player()->tau(), ev[2].tau);
        QCOMPARE(view.displayedState(), displayStateOf(ev[2].kind));
        QCOMPARE(log->logModel()->current(), 2);
    }

    void speedIsClampedAndScales() {
        TeachingPlayer player;
        player.setRun({}, 100.0, 0.1);
        player.setSpeed(50.0);
        QCOMPARE(player.speed(), TeachingPlayer::kMaxSpeed);
        player.setSpeed(0.0);
        QCOMPARE(player.speed(), TeachingPlayer::kMinSpeed);
        player.setSpeed(2.0);
        player.advance(0.5); // 0.5 s at 2x with t* = 0.1 s: tau = 0.5 * 2 / 0.1 = 10
        QCOMPARE_LE(std::abs(player.tau() - 10.0), 1e-12);
    }
};

QTEST_MAIN(TestTeachingPlayer)
#include "tst_teaching_player.moc"
