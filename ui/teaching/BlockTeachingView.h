// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The Teaching tab's free-standing block: the block animated from core's recorded path
// (rocking about either corner, impacts, sliding, overturning), its theta/alpha and base
// acceleration traces with a cursor, the transport of the slab's view (play, pause, speed,
// scrub, event steps: the same TeachingPlayer, its time in seconds) and one-click presets of
// the published cases (ui/teaching/BlockPresets.h).

#include "ui/Units.h"
#include "ui/teaching/BlockRun.h"
#include "ui/teaching/TransportBar.h"

#include <QWidget>

#include <memory>

class QComboBox;
class QLabel;
class QListWidget;
class QSlider;
class QToolButton;

namespace kinstab::ui {

class BlockAnimation;
class BlockTraces;
class TeachingPlayer;

class BlockTeachingView : public QWidget {
    Q_OBJECT
public:
    static constexpr int kScrubSteps = TransportBar::kScrubSteps;
    static constexpr double kDefaultSpeed = 0.5;

    explicit BlockTeachingView(QWidget* parent = nullptr);
    ~BlockTeachingView() override;

    const BlockRun& run() const { return *run_; }
    TeachingPlayer* player() const { return player_; }
    BlockAnimation* animation() const { return animation_; }
    QSlider* scrubber() const;
    QString currentPresetId() const { return presetId_; }
    // What the drawing shows now.
    RockingSample displayedState() const;

public slots:
    bool applyPreset(const QString& id); // false for an unknown id
    void setCase(const kinstab::ui::BlockCase& c);
    void setUnitSystem(kinstab::ui::UnitSystem s);

signals:
    void runChanged();

private:
    QWidget* buildTransport();
    void installKeys();
    QWidget* buildSidePanel();
    void rerun(const BlockCase& c);
    void showFrame(double t);
    void updateOutcome();

    std::unique_ptr<BlockRun> run_;
    TeachingPlayer* player_;
    BlockAnimation* animation_;
    BlockTraces* traces_;
    QComboBox* presets_ = nullptr;
    QLabel* caption_ = nullptr;
    QLabel* outcome_ = nullptr;
    QListWidget* events_ = nullptr;
    TransportBar* transport_ = nullptr;
    QString presetId_;
    UnitSystem units_ = UnitSystem::SI;
};

} // namespace kinstab::ui
