// SPDX-License-Identifier: GPL-3.0-or-later
// Screenshots of the Teaching view at a slip and at collapse (issue #9), rendered offscreen with
// grab(). Written to $KINSTAB_SCREENSHOT_DIR when set (docs/screenshots/ holds the committed
// ones), else to a temporary folder; the test checks the view shows the state it claims.

#include "ui/teaching/SurfaceMarker.h"
#include "ui/teaching/TeachingPlayer.h"
#include "ui/teaching/TeachingView.h"

#include <QDir>
#include <QImage>
#include <QTemporaryDir>
#include <QtTest>

using namespace kinstab;
using namespace kinstab::ui;

class TestTeachingScreenshots : public QObject {
    Q_OBJECT
private:
    QTemporaryDir tmp_;
    QString dir() const {
        const QString env = qEnvironmentVariable("KINSTAB_SCREENSHOT_DIR");
        return env.isEmpty() ? tmp_.path() : env;
    }
    void shoot(TeachingView& view, const QString& name) {
        QTRY_VERIFY_WITH_TIMEOUT(
            view.surfaceMarker()->hasMap() && !view.surfaceMarker()->isComputing(), 30000);
        const QString path = QDir(dir()).filePath(name);
        QVERIFY(view.grab().save(path));
        const QImage img(path);
        QCOMPARE(img.size(), view.size());
    }

private slots:
    void slip() {
        // Fig. 29's run (moderate envelope, A = 1.0, f = 1.0 Hz): stop in the middle of a slip
        // late in the run, where delta is large.
        TeachingView view;
        view.resize(1400, 900);
        view.show();
        QVERIFY(view.applyPreset(QStringLiteral("fig29")));
        const auto& ev = view.run().events();
        QVERIFY(ev.size() > 4);
        int k = static_cast<int>(ev.size()) - 2;
        while (k > 0 && ev[static_cast<std::size_t>(k)].kind != EventKind::SlipOnset)
            --k;
        QVERIFY(k > 0);
        const double t0 = ev[static_cast<std::size_t>(k)].tau,
                     t1 = ev[static_cast<std::size_t>(k + 1)].tau;
        view.player()->seek(t0 + 0.6 * (t1 - t0));
        QCOMPARE(view.displayedState(), DisplayState::Slip);
        shoot(view, QStringLiteral("teaching-slip.png"));
    }
    void collapse() {
        TeachingView view;
        view.resize(1400, 900);
        view.show();
        QVERIFY(view.applyPreset(QStringLiteral("fig29")));
        QCOMPARE(view.run().result().outcome, Outcome::Collapsed);
        view.player()->seek(view.run().result().tauC + 1.6); // the free end on its way down
        QCOMPARE(view.displayedState(), DisplayState::Collapse);
        shoot(view, QStringLiteral("teaching-collapse.png"));
    }
    void planar() {
        // Fig. 39's planar run (f_y = 1 Hz), in the middle of its last slip: side and top views.
        TeachingView view;
        view.resize(1400, 900);
        view.show();
        QVERIFY(view.applyPreset(QStringLiteral("fig39")));
        const auto& ev = view.run().events();
        QVERIFY(ev.size() > 2);
        int k = static_cast<int>(ev.size()) - 2;
        while (k > 0 && ev[static_cast<std::size_t>(k)].kind != EventKind::SlipOnset)
            --k;
        const double t0 = ev[static_cast<std::size_t>(k)].tau;
        const double t1 = ev[static_cast<std::size_t>(k + 1)].tau;
        view.player()->seek(t0 + 0.6 * (t1 - t0));
        shoot(view, QStringLiteral("teaching-planar.png"));
    }
};

QTEST_MAIN(TestTeachingScreenshots)
#include "tst_teaching_screenshots.moc"
