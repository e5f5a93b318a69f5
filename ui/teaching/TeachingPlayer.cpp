// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/teaching/TeachingPlayer.h"

#include <algorithm>
#include <cmath>

namespace kinstab::ui {

TeachingPlayer::TeachingPlayer(QObject* parent) : QObject(parent) {
    timer_.setInterval(16); // ~60 frames per second
    timer_.setTimerType(Qt::PreciseTimer);
    connect(&timer_, &QTimer::timeout, this, &TeachingPlayer::onTick);
}

void TeachingPlayer::setRun(std::vector<double> eventTimes, double tauEnd, double tstar) {
    events_ = std::move(eventTimes);
    tauEnd_ = std::max(0.0, tauEnd);
    tstar_ = tstar > 0.0 ? tstar : 0.099;
    tau_ = tau_ <= tauEnd_ ? tau_ : 0.0;
    reported_ = eventsBefore(tau_) - 1; // events at tau itself count as reached on the next move
    emit tauChanged(tau_);
}

int TeachingPlayer::eventIndex() const {
    const auto it = std::upper_bound(events_.begin(), events_.end(), tau_);
    return static_cast<int>(it - events_.begin()) - 1;
}

void TeachingPlayer::play() {
    if (playing_) return;
    if (atEnd()) moveTo(0.0); // play again from the start
    playing_ = true;
    elapsed_.start();
    timer_.start();
    emit playingChanged(true);
}

void TeachingPlayer::pause() {
    if (!playing_) return;
    playing_ = false;
    timer_.stop();
    emit playingChanged(false);
}

void TeachingPlayer::togglePlay() {
    playing_ ? pause() : play();
}

void TeachingPlayer::setSpeed(double speed) {
    const double s = std::isfinite(speed) ? std::clamp(speed, kMinSpeed, kMaxSpeed) : 1.0;
    if (s == speed_) return;
    speed_ = s;
    emit speedChanged(s);
}

void TeachingPlayer::seek(double tau) {
    if (!std::isfinite(tau)) return;
    moveTo(std::clamp(tau, 0.0, tauEnd_));
}

void TeachingPlayer::seekToEvent(int index) {
    if (index < 0 || index >= static_cast<int>(events_.size())) return;
    moveTo(events_[static_cast<std::size_t>(index)]);
}

void TeachingPlayer::stepToNextEvent() {
    pause();
    const auto it = std::upper_bound(events_.begin(), events_.end(), tau_);
    moveTo(it == events_.end() ? tauEnd_ : *it);
}

void TeachingPlayer::stepToPreviousEvent() {
    pause();
    const auto it = std::lower_bound(events_.begin(), events_.end(), tau_);
    moveTo(it == events_.begin() ? 0.0 : *std::prev(it));
}

void TeachingPlayer::advance(double realSeconds) {
    if (!(realSeconds > 0.0)) return;
    moveTo(std::min(tauEnd_, tau_ + realSeconds * speed_ / tstar_));
}

void TeachingPlayer::moveTo(double tau) {
    if (tau < tau_) reported_ = eventsBefore(tau) - 1; // going back: forget what lies ahead
    tau_ = tau;
    // Events reached by this move (at or before tau, not yet reported): once each, in order.
    const int reached = eventIndex();
    if (reached > reported_) emit eventsPassed(reported_ + 1, reached);
    reported_ = std::max(reported_, reached);
    emit tauChanged(tau_);
    if (tau_ >= tauEnd_ && playing_) {
        pause();
        emit finished();
    }
}

int TeachingPlayer::eventsBefore(double tau) const {
    return static_cast<int>(std::lower_bound(events_.begin(), events_.end(), tau) -
                            events_.begin());
}

void TeachingPlayer::onTick() {
    const double dt = static_cast<double>(elapsed_.restart()) / 1000.0;
    advance(std::min(dt, 0.1)); // a stalled event loop must not jump the animation
}

} // namespace kinstab::ui
