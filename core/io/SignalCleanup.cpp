// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/io/SignalCleanup.h"

#include <climits>
#include <csignal>
#include <cstring>
#include <unistd.h>

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

extern "C" void removeAndStop(int signal) {
    const int saved = errno;
    for (Slot& s : slots)
        if (s.state.load(std::memory_order_acquire) == kArmed) ::unlink(s.path);
    // SA_RESETHAND restored the default action: the signal, pending until this handler returns,
    // then ends the process as it would have without the handler (exit status 128 + signal).
    ::raise(signal);
    errno = saved;
}

} // namespace

void removeTemporariesOnSignals() {
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
