// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The codes a project selects, each with its own inputs: a code is selected when its inputs
// are present. Runs them all on one building, in a fixed order.

#include "core/codes/Asce7_22.h"
#include "core/codes/Atc306.h"
#include "core/codes/Eurocode8.h"
#include "core/codes/Ubc1976.h"
#include "core/codes/Ubc1997.h"

#include <optional>
#include <string_view>
#include <vector>

namespace kinstab {

struct CodeSelection {
    std::optional<Ubc1976Inputs> ubc1976;
    std::optional<Atc306Inputs> atc306;
    std::optional<Ubc1997Inputs> ubc1997;
    std::optional<Asce7Inputs> asce7_22;
    std::optional<Eurocode8Inputs> ec8;

    bool empty() const { return !ubc1976 && !atc306 && !ubc1997 && !asce7_22 && !ec8; }
};

// Keys in output order: ubc1976, atc306, ubc1997, asce7_22, ec8.
std::vector<std::string> codeKeys();

// Whether the selection holds the code with JSON key `id`.
bool isSelected(const CodeSelection& codes, std::string_view id);

std::string validateCodes(const CodeSelection& codes); // empty when fine, names "<key>.<field>"

// Throws InputError on a bad building or inputs; nothing is computed then.
std::vector<CodeResult> runCodes(const Building& b, const CodeSelection& codes);

} // namespace kinstab
