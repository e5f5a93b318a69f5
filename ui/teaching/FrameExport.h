// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Export of what the Teaching view shows: the current frame (drawing above, traces below) as
// PNG or SVG, and a whole run as a numbered PNG sequence (frame_00000.png, ...) for slides
// and video tools.

#include "ui/Units.h"
#include "ui/teaching/TeachingRun.h"

#include <QRectF>
#include <QSize>
#include <QString>

#include <functional>

class QPainter;

namespace kinstab::ui {

// Drawing in the upper 55 %, traces below.
void paintTeachingFrame(QPainter& p, const QRectF& area, const TeachingRun& run, double tau,
                        UnitSystem units = UnitSystem::SI);

// Each returns an empty string on success, else a message naming the file.
QString saveFramePng(const QString& path, const TeachingRun& run, double tau,
                     QSize size = {1280, 900}, UnitSystem units = UnitSystem::SI);
QString saveFrameSvg(const QString& path, const TeachingRun& run, double tau,
                     QSize size = {1280, 900}, UnitSystem units = UnitSystem::SI);

struct SequenceOptions {
    double framesPerSecond = 25;
    double speed = 1.0;                // as the player's: 1x = real time
    UnitSystem units = UnitSystem::SI; // lengths in the drawing
    QSize size{960, 675};
    int maxFrames = 20000;
};

struct SequenceResult {
    int frames = 0;
    QString error;
    bool cancelled = false;
};

// Frames at tau = k * speed / (fps t*) for k = 0.. up to the run's end (always ending on the
// last frame of the run). progress(done, total) returns false to cancel.
SequenceResult saveFrameSequence(const QString& directory, const TeachingRun& run,
                                 const SequenceOptions& o,
                                 const std::function<bool(int, int)>& progress = {});

} // namespace kinstab::ui
