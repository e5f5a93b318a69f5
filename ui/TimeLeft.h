// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A time-left estimate that does not jump about: the rate (units per second) is smoothed over
// the last few seconds (an exponential moving average with a 3 s time constant), so one slow
// or fast poll moves it a little, and it is not shown before a second of the run has passed.

#include <cstddef>
#include <optional>

namespace kinstab::ui {

class TimeLeft {
public:
    static constexpr double timeConstantSeconds = 3.0;
    static constexpr double warmUpSeconds = 1.0;

    void reset();
    // A poll at `seconds` since the start: `done` of `total` units finished.
    void update(double seconds, std::size_t done, std::size_t total);
    // Units per second, smoothed; 0 before the first units are done.
    double rate() const { return m_rate; }
    // Seconds to go; none during the warm-up or while nothing is done.
    std::optional<double> secondsLeft() const;

private:
    double m_lastSeconds = 0;
    std::size_t m_lastDone = 0;
    std::size_t m_remaining = 0;
    double m_rate = 0;
    bool m_haveRate = false;
};

} // namespace kinstab::ui
