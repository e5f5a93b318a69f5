// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Physical constants, each written once.

namespace kinstab {

// Standard gravity, m/s² (CGPM 1901): records in m/s² and t* = √(d / 2g) read this one value.
inline constexpr double kStandardGravity = 9.80665;

} // namespace kinstab
