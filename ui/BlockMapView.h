// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The main result view of the free-standing block model: its overturning map
// (ui/OverturningMapPlot.h) under the chosen equations with the other equations' boundary drawn
// over it, both computed by core's overturningMap on core's thread pool through a BackgroundJob
// (progress, cancel; the GUI never waits). A map made with other inputs than the panel shows is
// dimmed with "inputs changed — Run to update", as the γc surface is. Hovering a point reads it
// out in the line below.

#include "core/rocking/BlockMapSettings.h"
#include "ui/Units.h"

#include <QWidget>

#include <optional>

class QLabel;

namespace kinstab::ui {

class BackgroundJob;
struct JobContext;
class OverturningMapPlot;
class StaleFrame;

struct BlockMapResult {
    BlockMapSettings settings;           // what it was computed with (selected: true)
    OverturningMap main;                 // the chosen equations
    std::optional<OverturningMap> other; // the other equations (none if cancelled before it)
};

// Both maps of the settings, cancellable through the job's control; counts 2 points² units.
// Pure but for the context it advances: the tests call it too.
BlockMapResult computeBlockMaps(const BlockMapSettings& s, JobContext& job);

class BlockMapView : public QWidget {
    Q_OBJECT
public:
    explicit BlockMapView(QWidget* parent = nullptr);

    void run(const BlockMapSettings& s); // supersedes a run still going
    void cancel();
    void clear(); // New/Open: the run stops, the map goes
    bool isRunning() const;
    BackgroundJob* job() const { return m_job; }
    // The last complete result (a cancelled run keeps the one before).
    const std::optional<BlockMapResult>& result() const { return m_result; }
    // The inputs the panel shows now: the map is stale when it was made with others.
    void setInputs(const BlockMapSettings& s);
    bool isStale() const;
    void setUnitSystem(UnitSystem s);
    OverturningMapPlot* plot() const { return m_plot; }
    // "ω_p/p = …, a_p/(αg) = …: overturns …" for a point of the map (empty outside it).
    QString readout(int frequencyIndex, int amplitudeIndex) const;
    QString readoutText() const;

signals:
    void started(qint64 total);
    void progress(qint64 done, qint64 total);
    // After a run: complete false when cancelled (the previous map stays).
    void finished(bool complete, const QString& message);

private:
    void deliver(BlockMapResult r);
    void updateHeader();

    OverturningMapPlot* m_plot;
    StaleFrame* m_frame;
    QLabel* m_header;
    QLabel* m_readout;
    BackgroundJob* m_job;
    std::optional<BlockMapResult> m_result;
    BlockMapSettings m_inputs;
    UnitSystem m_units = UnitSystem::SI;
};

// "one-sine pulse, exact equations" and the like, for titles.
QString blockMapTitle(const BlockMapSettings& s);

} // namespace kinstab::ui
