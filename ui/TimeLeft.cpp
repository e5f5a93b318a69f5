// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/TimeLeft.h"

#include <cmath>

namespace kinstab::ui {

void TimeLeft::reset() {
    *this = TimeLeft();
}

void TimeLeft::update(double seconds, std::size_t done, std::size_t total) {
    m_remaining = total > done ? total - done : 0;
    const double dt = seconds - m_lastSeconds;
    if (!(dt > 0) || done < m_lastDone) return;
    const double instant = static_cast<double>(done - m_lastDone) / dt;
    if (!m_haveRate && done > 0) {
        m_rate = static_cast<double>(done) / seconds; // the first look: the average so far
        m_haveRate = true;
    } else if (m_haveRate) {
        const double weight = 1.0 - std::exp(-dt / timeConstantSeconds);
        m_rate += weight * (instant - m_rate);
    }
    m_lastSeconds = seconds;
    m_lastDone = done;
}

std::optional<double> TimeLeft::secondsLeft() const {
    if (!m_haveRate || m_lastSeconds < warmUpSeconds || !(m_rate > 0)) return std::nullopt;
    return static_cast<double>(m_remaining) / m_rate;
}

} // namespace kinstab::ui
