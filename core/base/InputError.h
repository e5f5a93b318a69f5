// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Bad input anywhere in core: the message names the field, the value and the allowed range.
// Nothing is computed from bad input. It sits on the bottom floor so every folder can throw it.

#include <stdexcept>

namespace kinstab {

struct InputError : std::invalid_argument {
    using std::invalid_argument::invalid_argument;
};

} // namespace kinstab
