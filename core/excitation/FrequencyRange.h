// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The frequencies an enveloped sine accepts, in Hz (the command line's --frequency,
// --frequencies and --fy, and the project files).
//
// Lower limit, 1e-3 Hz (a 1000 s period). Physics: f is a building's fundamental frequency,
// and no building sways slower than about 0.1 Hz; 1e-3 Hz leaves a factor 100. Numerics: the
// solvers walk the time line by half-periods of the sine and look for peaks of |a| in each;
// as f -> 0 a half-period outlasts the envelope itself (f = 1e-4 Hz and the moderate envelope:
// e(t) is below 1e-308 before the first half-period ends), a(tau) is then a single pulse whose
// shape no longer depends on f, and the peak searches work on quantities at the edge of the
// double range. At 1e-3 Hz every preset envelope still holds more than 1e-33 of its peak at
// the end of the first half-period (moderate: 2.7e-33), so every intermediate stays well inside
// that range.

namespace kinstab {

inline constexpr double kMinFrequencyHz = 1e-3;
inline constexpr double kMaxFrequencyHz = 1000.0;

} // namespace kinstab
