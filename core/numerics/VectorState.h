// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Code built for baseline x86-64 (ours, and the legacy-SSE paths it calls) runs many times slower
// while the upper halves of the AVX registers are "dirty": each SSE instruction then pays the
// SSE/AVX transition penalty. Code that uses 256-bit AVX must clear them (vzeroupper) when done;
// not all does. Measured on this project's machine: once libQt6Qml is loaded (Qt Data
// Visualization pulls it into both executables) its start-up leaves them dirty, every thread
// started afterwards inherits that, and a sin/exp loop takes 1.96 s instead of 0.079 s; the
// 257 x 257 surface took 6.1 s instead of 0.8 s. Clearing the state where numerical work starts
// restores full speed; it costs one instruction. Since kinstab-cli links the report library on Qt
// Gui only (no Data Visualization, no Qml) it does not need this: `kinstab-cli bench
// --vector-state`, 257 x 257 exact surface, 7 alternating runs, CPU median 0.937 s without
// against 0.936 s with (ratio 1.000). The GUI still loads Qml, so the solvers keep the call.

#include <atomic>

namespace kinstab {

// On by default; off only in `kinstab-cli bench --vector-state`, which times the surface with and
// without the clearing in one process to show whether this workaround still pays.
inline std::atomic<bool>& upperVectorStateClearing() {
    static std::atomic<bool> on{true};
    return on;
}

inline void clearUpperVectorState() {
    if (!upperVectorStateClearing().load(std::memory_order_relaxed)) return;
#if defined(__x86_64__) && defined(__GNUC__)
    if (__builtin_cpu_supports("avx")) __asm__ volatile("vzeroupper" ::: "memory");
#endif
}

} // namespace kinstab
