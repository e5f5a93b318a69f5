// SPDX-License-Identifier: GPL-3.0-or-later
// Export of the Teaching view (issue #9): the current frame as PNG and SVG, and a whole run
// as a numbered PNG sequence; a bad folder gets a message naming it.

#include "ui/teaching/FrameExport.h"
#include "ui/teaching/StateStyle.h"
#include "ui/teaching/TeachingPlayer.h"
#include "ui/teaching/TeachingView.h"

#include <QDir>
#include <QFile>
#include <QImage>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>

using namespace kinstab;
using namespace kinstab::ui;

class TestTeachingExport : public QObject {
    Q_OBJECT
private slots:
    void framePng() {
        QTemporaryDir tmp;
        TeachingView view;
        view.applyPreset(QStringLiteral("fig35"));
        view.player()->seek(30.0);
        const QString path = tmp.filePath(QStringLiteral("frame.png"));
        QCOMPARE(view.exportFramePng(path, QSize(800, 560)), QString());
        const QImage img(path);
        QCOMPARE(img.size(), QSize(800, 560));
        // Drawn, not blank: the slab's fill in the colour of the state shown is in the picture.
        const QColor slab = stateColor(view.displayedState()).lighter(115);
        int slabPixels = 0;
        for (int y = 0; y < img.height(); ++y)
            for (int x = 0; x < img.width(); ++x)
                slabPixels += img.pixel(x, y) == slab.rgb();
        QCOMPARE_GE(slabPixels, 1000);
    }

    void frameSvg() {
        QTemporaryDir tmp;
        TeachingView view;
        view.applyPreset(QStringLiteral("fig29"));
        view.player()->seek(view.run().result().tauC);
        const QString path = tmp.filePath(QStringLiteral("frame.svg"));
        QCOMPARE(view.exportFrameSvg(path), QString());
        QFile f(path);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QByteArray svg = f.readAll();
        QVERIFY(svg.contains("<svg"));
        QVERIFY(svg.contains("<path")); // vector lines, not an embedded bitmap
        QVERIFY(!svg.contains("<image"));
        QVERIFY(svg.contains("COLLAPSE")); // text stays text
    }

    void sequenceWritesEveryFrame() {
        QTemporaryDir tmp;
        TeachingView view;
        TeachingParams p = view.params();
        p.amplitude = 1.15; // collapses early on the moderate envelope
        view.setParams(p);
        view.player()->setSpeed(10.0);
        const double fps = 5;
        // Frames at tau = k * speed / (fps t*) up to the end: ceil(end / dTau) + 1 of them.
        const double dTau = 10.0 / (fps * view.run().tstar());
        const int want = static_cast<int>(std::ceil(view.run().displayEnd() / dTau - 1e-9)) + 1;
        QString error;
        const int n = view.exportSequence(tmp.path(), fps, QSize(320, 240), &error);
        QCOMPARE(error, QString());
        QCOMPARE(n, want);
        const QStringList files =
            QDir(tmp.path()).entryList({QStringLiteral("frame_*.png")}, QDir::Files, QDir::Name);
        QCOMPARE(files.size(), want);
        QCOMPARE(files.first(), QStringLiteral("frame_00000.png"));
        QCOMPARE(files.last(),
                 QStringLiteral("frame_%1.png").arg(want - 1, 5, 10, QLatin1Char('0')));
        QCOMPARE(QImage(QDir(tmp.path()).filePath(files.last())).size(), QSize(320, 240));
    }

    void badFolderIsNamed() {
        TeachingView view;
        QString error;
        QCOMPARE(view.exportSequence(QStringLiteral("/proc/kinstab-no-such/dir"), 25,
                                     QSize(100, 100), &error),
                 0);
        QVERIFY(error.contains(QStringLiteral("/proc/kinstab-no-such/dir")));
        QVERIFY(view.exportFramePng(QStringLiteral("/proc/kinstab-no-such/x.png"))
                    .contains(QStringLiteral("x.png")));
    }
};

QTEST_MAIN(TestTeachingExport)
#include "tst_teaching_export.moc"
