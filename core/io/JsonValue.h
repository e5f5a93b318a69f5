// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// An optional value as JSON: the value, or null where there is none (a record too short for a
// significant duration, a search that found no critical amplitude); finiteOrNull also writes an
// infinite or NaN value as null (an unbounded confidence bound), since JSON has no infinity. One
// rule for every writer, sorted (nlohmann::json) or ordered (nlohmann::ordered_json), beside
// them in io: the floors below compute values and write no JSON.

#include <nlohmann/json.hpp>

#include <cmath>
#include <optional>

namespace kinstab {

template <class Json = nlohmann::json, class T> Json orNull(const std::optional<T>& x) {
    return x ? Json(*x) : Json();
}

template <class Json = nlohmann::json> Json finiteOrNull(const std::optional<double>& x) {
    return x && std::isfinite(*x) ? Json(*x) : Json();
}

} // namespace kinstab
