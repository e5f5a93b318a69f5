// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// std::nextafter without libm's call in the common case: the planar solver asks for the double
// next to a window's end about a million times per surface with a vertical record (issue 34: the
// call was 0.7 % of the instructions). For a positive finite x the neighbours are one unit of the
// bit pattern away (the IEEE 754 binary64 encoding orders positive doubles as integers); every
// other case goes to std::nextafter, so the result is its, bit for bit.

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

namespace kinstab {

inline double nextAfter(double x, double toward) {
    if (x > 0.0 && x < std::numeric_limits<double>::infinity()) {
        const auto bits = std::bit_cast<std::uint64_t>(x);
        if (toward > x) return std::bit_cast<double>(bits + 1);
        if (toward < x) return std::bit_cast<double>(bits - 1);
    }
    return std::nextafter(x, toward);
}

} // namespace kinstab
