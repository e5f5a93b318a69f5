// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The interval an input must lie in. A validator in core and the input field that shows the
// same value read one Range, so the field never accepts what the run refuses.

namespace kinstab {

struct Range {
    double lo;
    double hi;
    bool loOpen = false; // lo < x rather than lo <= x (a coefficient that must not be zero)

    constexpr bool contains(double x) const {
        return (loOpen ? x > lo : x >= lo) && x <= hi; // false for NaN
    }
};

} // namespace kinstab
