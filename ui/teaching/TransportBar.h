// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The teaching views' play bar, for the slab and the block alike: back to the start, previous
// event, play/pause, next event, a scrub slider over the run, the time shown and the speed. It
// drives a TeachingPlayer and follows it (the play icon, the speed, the position).

#include <QString>
#include <QWidget>

#include <functional>

class QComboBox;
class QLabel;
class QSlider;
class QToolButton;

namespace kinstab::ui {

class TeachingPlayer;

class TransportBar : public QWidget {
public:
    static constexpr int kScrubSteps = 10000;

    struct Texts {
        QString nextEventTip; // what "next event" steps to in this view
        QString speedTip;     // what 1× means in this view
        int timeWidth = 120;  // room for the time text, px
    };
    // end: the run's end in the player's time (the scrub slider spans [0, end]).
    TransportBar(TeachingPlayer* player, std::function<double()> end, const Texts& texts,
                 QWidget* parent = nullptr);

    // Space plays and pauses, N and B step between events, wherever the focus is inside view.
    void installKeys(QWidget* view);
    // The slider at `at` of the run's end (without seeking back) and the time text beside it.
    void showPosition(double at, const QString& timeText);
    QSlider* scrubber() const { return scrub_; }

private:
    void buildButtons(const Texts& texts);
    void buildSpeed(const Texts& texts);

    TeachingPlayer* player_;
    std::function<double()> end_;
    QToolButton* playButton_ = nullptr;
    QSlider* scrub_ = nullptr;
    QLabel* timeLabel_ = nullptr;
    QComboBox* speed_ = nullptr;
};

} // namespace kinstab::ui
