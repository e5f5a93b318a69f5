// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A progress line on stderr for a long run, while stderr is a terminal: "surface: 4500/90000
// points (5 %), 1200/s, 1:15 left", redrawn twice a second from a watcher thread that polls
// the run's counters, and wiped when the run ends. Silent when stderr is a file or a pipe, so
// scripts and logs see only the result. Runs shorter than the first half second show nothing.

#include <condition_variable>
#include <cstddef>
#include <functional>
#include <mutex>
#include <string>
#include <thread>
#include <utility>

namespace kinstab::cli {

// "1:15", "12:03", "2:05:00": the time left, for the progress line.
std::string clockText(double seconds);
// The line itself (without "\r"): name, done/total unit, percent, rate and time left.
std::string progressText(const std::string& name, const std::string& unit, std::size_t done,
                         std::size_t total, double seconds);

class ProgressLine {
public:
    // poll returns (done, total); it is called from the watcher thread and must be thread-safe.
    ProgressLine(std::string name, std::string unit,
                 std::function<std::pair<std::size_t, std::size_t>()> poll);
    ~ProgressLine(); // stops the watcher and wipes the line
    ProgressLine(const ProgressLine&) = delete;
    ProgressLine& operator=(const ProgressLine&) = delete;

private:
    void watch();

    std::string name_, unit_;
    std::function<std::pair<std::size_t, std::size_t>()> poll_;
    std::mutex mutex_;
    std::condition_variable wake_;
    bool stop_ = false;
    bool shown_ = false;
    std::thread thread_;
};

} // namespace kinstab::cli
