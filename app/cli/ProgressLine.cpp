// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli/ProgressLine.h"

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>

namespace kinstab::cli {

std::string clockText(double seconds) {
    const long s = std::lround(std::max(0.0, std::min(seconds, 359999.0))); // < 100 h
    char buf[32];
    if (s >= 3600)
        std::snprintf(buf, sizeof buf, "%ld:%02ld:%02ld", s / 3600, s / 60 % 60, s % 60);
    else
        std::snprintf(buf, sizeof buf, "%ld:%02ld", s / 60, s % 60);
    return buf;
}

std::string progressText(const std::string& name, const std::string& unit, std::size_t done,
                         std::size_t total, double seconds) {
    std::string t = name + ": " + std::to_string(done) + "/" + std::to_string(total) + " " + unit;
    if (total > 0) t += " (" + std::to_string(100 * done / total) + " %)";
    if (done == 0 || seconds <= 0.0) return t;
    const double rate = static_cast<double>(done) / seconds;
    // Integers only: no decimal point for a locale to change.
    t += ", " + std::to_string(std::llround(rate)) + "/s";
    if (total > done) t += ", " + clockText(static_cast<double>(total - done) / rate) + " left";
    return t;
}

ProgressLine::ProgressLine(std::string name, std::string unit,
                           std::function<std::pair<std::size_t, std::size_t>()> poll)
    : name_(std::move(name)), unit_(std::move(unit)), poll_(std::move(poll)) {
    if (::isatty(STDERR_FILENO) != 1) return; // a log or a pipe: the result only
    thread_ = std::thread([this] { watch(); });
}

ProgressLine::~ProgressLine() {
    if (!thread_.joinable()) return;
    {
        const std::lock_guard<std::mutex> lock(mutex_);
        stop_ = true;
    }
    wake_.notify_all();
    thread_.join();
    if (shown_) std::cerr << "\r\033[K" << std::flush; // the result follows on a clean line
}

void ProgressLine::watch() {
    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    std::unique_lock<std::mutex> lock(mutex_);
    // Bounded by the run: the destructor sets stop_ when it ends.
    while (!wake_.wait_for(lock, std::chrono::milliseconds(500), [this] { return stop_; })) {
        const auto [done, total] = poll_();
        const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
        std::cerr << "\r\033[K" << progressText(name_, unit_, done, total, seconds) << std::flush;
        shown_ = true;
    }
}

} // namespace kinstab::cli
