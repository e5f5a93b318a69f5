// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/sweep/ParallelFor.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace kinstab {

int poolThreads(int threads, std::size_t n) {
    const std::size_t want = threads > 0
                                 ? static_cast<std::size_t>(threads)
                                 : std::max<std::size_t>(1, std::thread::hardware_concurrency());
    return static_cast<int>(std::min(want, std::max<std::size_t>(n, 1)));
}

void parallelFor(std::size_t n, int threads, const SweepControl* control,
                 const std::function<void(std::size_t)>& body) {
    std::atomic<std::size_t> next{0};
    std::atomic<bool> failed{false};
    std::mutex mutex;
    std::size_t firstFailure = n; // guarded by mutex
    std::exception_ptr error;     // of firstFailure
    auto worker = [&] {
        while (!failed.load(std::memory_order_acquire) && !(control && control->isCancelled())) {
            const std::size_t k = next.fetch_add(1, std::memory_order_relaxed);
            if (k >= n) return;
            try {
                body(k);
            } catch (...) {
                std::lock_guard lock(mutex);
                if (k < firstFailure) firstFailure = k, error = std::current_exception();
                failed.store(true, std::memory_order_release);
            }
        }
    };
    std::vector<std::thread> pool;
    for (int i = 1; i < poolThreads(threads, n); ++i)
        pool.emplace_back(worker);
    worker();
    for (auto& t : pool)
        t.join();
    if (error) std::rethrow_exception(error);
}

} // namespace kinstab
