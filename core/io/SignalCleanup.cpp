// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/io/SignalCleanup.h"

#include <climits>
#include <csignal>
#include <cstring>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>

namespace kinstab {

namespace {

// The handler reads these while any thread may arm or disarm a slot: lock-free atomics are
// safe to use from a signal handler (C++17 [support.signal]).
static_assert(std::atomic<int>::is_always_lock_free);

enum SlotState : int { kFree = 0, kFilling = 1, kArmed = 2 };
constexpr int kSlots = 16;

struct Slot {
    std::atomic<int> state{kFree};
    char path[PATH_MAX];
};
Slot slots[kSlots];

// The line the handler writes, prepared at start-up: nothing is formatted in the handler.
char stopName[256] = {};
std::size_t stopNameLength = 0;
bool stderrIsTerminal = false;

void writeAll(const char* text, std::size_t n) {
    while (n > 0) {
        const ssize_t w = ::write(STDERR_FILENO, text, n);
        if (w <= 0) return;
        text += w;
        n -= static_cast<std::size_t>(w);
    }
}

void sayStopped(int signal) {
    if (stopNameLength == 0 || signal == SIGHUP) return;
    if (stderrIsTerminal) writeAll("\r\033[K", 4); // over the progress line, if any
    writeAll(stopName, stopNameLength);
    if (signal == SIGINT)
        writeAll(": interrupted (SIGINT)\n", 23);
    else
        writeAll(": stopped (SIGTERM)\n", 20);
}

extern "C" void removeAndStop(int signal) {
    const int saved = errno;
    for (Slot& s : slots)
        if (s.state.load(std::memory_order_acquire) == kArmed) ::unlink(s.path);
    sayStopped(signal);
    // SA_RESETHAND restored the default action: the signal, pending until this handler returns,
    // then ends the process as it would have without the handler (exit status 128 + signal).
    ::raise(signal);
    errno = saved;
}

} // namespace

void removeTemporariesOnSignals(const char* name) {
    if (name) {
        stopNameLength = std::min(std::strlen(name), sizeof stopName - 1);
        std::memcpy(stopName, name, stopNameLength);
        stderrIsTerminal = ::isatty(STDERR_FILENO) == 1;
    }
    struct sigaction action {};
    action.sa_handler = removeAndStop;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESETHAND;
    for (int signal : {SIGINT, SIGTERM, SIGHUP})
        ::sigaction(signal, &action, nullptr);
}

RemovedOnSignal::RemovedOnSignal(const std::string& path) {
    if (path.size() >= PATH_MAX) return;
    for (int i = 0; i < kSlots; ++i) {
        int expected = kFree;
        if (!slots[i].state.compare_exchange_strong(expected, kFilling)) continue;
        std::memcpy(slots[i].path, path.c_str(), path.size() + 1);
        slots[i].state.store(kArmed, std::memory_order_release);
        slot_ = i;
        return;
    }
}

void RemovedOnSignal::disarm() {
    if (slot_ < 0) return;
    slots[slot_].state.store(kFree, std::memory_order_release);
    slot_ = -1;
}

} // namespace kinstab
