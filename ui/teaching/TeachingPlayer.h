// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The Teaching view's clock: plays dimensionless time tau at a chosen speed (1x = real time,
// tau advancing 1/t* per second), pauses, scrubs and steps from event to event. The QTimer
// only feeds advance(); tests call advance() directly, so nothing depends on wall time.

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>

#include <vector>

namespace kinstab::ui {

class TeachingPlayer : public QObject {
    Q_OBJECT
public:
    static constexpr double kMinSpeed = 0.1;
    static constexpr double kMaxSpeed = 10.0;
    // Slow motion: a collapse at 1 Hz (tens of tau at t* = 0.1 s) lasts seconds, not a blink.
    static constexpr double kDefaultSpeed = 0.25;

    explicit TeachingPlayer(QObject* parent = nullptr);

    // A new run: event times (increasing), the end of the animation and t* (seconds).
    // Keeps the current tau when it lies inside the new run (a slider moved), else rewinds.
    void setRun(std::vector<double> eventTimes, double tauEnd, double tstar);

    double tau() const { return tau_; }
    double tauEnd() const { return tauEnd_; }
    double speed() const { return speed_; }
    bool isPlaying() const { return playing_; }
    bool atEnd() const { return tau_ >= tauEnd_; }
    // Index of the last event at or before tau (-1 before the first).
    int eventIndex() const;

public slots:
    void play();
    void pause();
    void togglePlay();
    void setSpeed(double speed); // clamped to [0.1, 10]
    void seek(double tau);       // clamped to [0, tauEnd]
    void seekToEvent(int index);
    void stepToNextEvent();
    void stepToPreviousEvent();
    void rewind() { seek(0.0); }
    // Move the clock by this much real time at the current speed (the timer's tick).
    void advance(double realSeconds);

signals:
    void tauChanged(double tau);
    // Events first..last were reached by the last move (at or before the new tau, not reported
    // since the clock last went back past them), in order: a fast tick can pass several, and
    // none is skipped.
    void eventsPassed(int first, int last);
    void playingChanged(bool playing);
    void speedChanged(double speed);
    void finished();

private:
    void moveTo(double tau);
    int eventsBefore(double tau) const; // number of events strictly before tau
    void onTick();

    std::vector<double> events_;
    int reported_ = -1; // last event reported by eventsPassed
    double tau_ = 0, tauEnd_ = 0, tstar_ = 0.099, speed_ = kDefaultSpeed;
    bool playing_ = false;
    QTimer timer_;
    QElapsedTimer elapsed_;
};

} // namespace kinstab::ui
