// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A project file written stably, for projects kept under version control: saving a file that
// was read changes only what the user changed. Keys come in the order the file had them (new
// keys after them, in the writer's order), and a list the file wrote as a LIST string
// ("0.70:1.15:0.05") is written as that string again while it still reads as the same numbers.

#include <nlohmann/json.hpp>

namespace kinstab {

// fresh (what the writer produced) arranged after layout (the document as read; null for a new
// file), then after order (keys a new file writes, in that order). Values are fresh's.
nlohmann::ordered_json arrangeLike(const nlohmann::json& fresh,
                                   const nlohmann::ordered_json& layout,
                                   const nlohmann::ordered_json& order = nullptr);

} // namespace kinstab
