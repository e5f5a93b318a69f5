// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/teaching/FrameExport.h"

#include "ui/AtomicSave.h"
#include "ui/teaching/SlabPainter.h"
#include "ui/teaching/TracePainter.h"

#include <QBuffer>
#include <QDir>
#include <QImage>
#include <QPainter>
#include <QSvgGenerator>

#include <algorithm>
#include <cmath>

namespace kinstab::ui {

void paintTeachingFrame(QPainter& p, const QRectF& area, const TeachingRun& run, double tau,
                        UnitSystem units) {
    const QRectF top(area.left(), area.top(), area.width(), area.height() * 0.55);
    const QRectF bottom(area.left(), top.bottom(), area.width(), area.height() - top.height());
    paintSlabScene(p, top,
                   SlabScene{run.frameAt(tau), run.params(), run.tstar(), run.displayEnd(),
                             run.exitSide(), units});
    paintTraces(p, bottom, run, tau);
}

namespace {
QImage renderImage(const TeachingRun& run, double tau, QSize size, UnitSystem units) {
    QImage img(size, QImage::Format_RGB32);
    img.fill(Qt::white);
    QPainter p(&img);
    paintTeachingFrame(p, QRectF(QPointF(0, 0), QSizeF(size)), run, tau, units);
    return img;
}
} // namespace

QString saveFramePng(const QString& path, const TeachingRun& run, double tau, QSize size,
                     UnitSystem units) {
    if (size.width() < 16 || size.height() < 16)
        return QStringLiteral("image size %1×%2 is too small").arg(size.width()).arg(size.height());
    return saveImageAtomically(path, renderImage(run, tau, size, units), "PNG");
}

QString saveFrameSvg(const QString& path, const TeachingRun& run, double tau, QSize size,
                     UnitSystem units) {
    QByteArray bytes; // in memory, then written whole (ui/AtomicSave.h)
    QBuffer buffer(&bytes);
    QSvgGenerator svg;
    svg.setOutputDevice(&buffer);
    svg.setSize(size);
    svg.setViewBox(QRect(QPoint(0, 0), size));
    svg.setTitle(QStringLiteral("kinstab teaching frame, τ = %1").arg(tau, 0, 'f', 3));
    svg.setDescription(QStringLiteral("Slab on its walls and the a(τ), δ(τ) traces"));
    QPainter p;
    if (!p.begin(&svg)) return QStringLiteral("cannot write %1").arg(path);
    paintTeachingFrame(p, QRectF(QPointF(0, 0), QSizeF(size)), run, tau, units);
    if (!p.end()) return QStringLiteral("cannot write %1").arg(path);
    return saveAtomically(path, bytes);
}

SequenceResult saveFrameSequence(const QString& directory, const TeachingRun& run,
                                 const SequenceOptions& o,
                                 const std::function<bool(int, int)>& progress) {
    SequenceResult r;
    if (!(o.framesPerSecond > 0) || !(o.speed > 0)) {
        r.error = QStringLiteral("frames per second (%1) and speed (%2) must be positive")
                      .arg(o.framesPerSecond)
                      .arg(o.speed);
        return r;
    }
    if (!QDir().mkpath(directory)) {
        r.error = QStringLiteral("cannot create the folder %1").arg(directory);
        return r;
    }
    const double dTau = o.speed / (o.framesPerSecond * run.tstar());
    const int total = static_cast<int>(std::ceil(run.displayEnd() / dTau - 1e-9)) + 1;
    if (total > o.maxFrames) {
        r.error =
            QStringLiteral(
                "%1 frames is more than the limit of %2: raise the speed or lower the frame rate")
                .arg(total)
                .arg(o.maxFrames);
        return r;
    }
    const QDir dir(directory);
    for (int k = 0; k < total; ++k) {
        if (progress && !progress(k, total)) {
            r.cancelled = true;
            return r;
        }
        const double tau = std::min(k * dTau, run.displayEnd());
        const QString file =
            dir.filePath(QStringLiteral("frame_%1.png").arg(k, 5, 10, QLatin1Char('0')));
        r.error = saveFramePng(file, run, tau, o.size, o.units);
        if (!r.error.isEmpty()) return r;
        r.frames = k + 1;
    }
    if (progress) progress(total, total);
    return r;
}

} // namespace kinstab::ui
