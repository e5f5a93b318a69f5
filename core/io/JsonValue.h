// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// An optional value as JSON: the value, or null where there is none (a record too short for a
// significant duration, a search that found no critical amplitude). One rule for every writer,
// sorted (nlohmann::json) or ordered (nlohmann::ordered_json).

#include <nlohmann/json.hpp>

#include <optional>

namespace kinstab {

template <class Json = nlohmann::json, class T> Json orNull(const std::optional<T>& x) {
    return x ? Json(*x) : Json();
}

} // namespace kinstab
