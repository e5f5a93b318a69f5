// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/io/ProjectLayout.h"

#include "core/sweep/Grid.h"

namespace kinstab {

using nlohmann::json;
using nlohmann::ordered_json;

namespace {

// The file's "0.70:1.15:0.05" when it still stands for exactly the numbers written now.
bool sameList(const json& numbers, const ordered_json& text) {
    if (!numbers.is_array() || !text.is_string()) return false;
    const ParsedList p = parseList(text.get<std::string>());
    if (!p.error.empty() || p.values.size() != numbers.size()) return false;
    for (std::size_t i = 0; i < p.values.size(); ++i)
        if (!numbers[i].is_number() || numbers[i].get<double>() != p.values[i]) return false;
    return true;
}

const ordered_json& memberOr(const ordered_json& o, const std::string& key) {
    static const ordered_json none;
    if (!o.is_object()) return none;
    const auto it = o.find(key);
    return it == o.end() ? none : *it;
}

ordered_json arrangeObject(const json& fresh, const ordered_json& layout,
                           const ordered_json& order) {
    ordered_json out = ordered_json::object();
    auto put = [&](const std::string& key) {
        if (!fresh.contains(key) || out.contains(key)) return;
        out[key] = arrangeLike(fresh.at(key), memberOr(layout, key), memberOr(order, key));
    };
    for (const ordered_json* o : {&layout, &order})
        if (o->is_object())
            for (const auto& item : o->items())
                put(item.key());
    for (const auto& item : fresh.items())
        put(item.key()); // json's own (sorted) order
    return out;
}

} // namespace

ordered_json arrangeLike(const json& fresh, const ordered_json& layout, const ordered_json& order) {
    if (fresh.is_object()) return arrangeObject(fresh, layout, order);
    if (sameList(fresh, layout)) return layout;
    if (fresh.is_array()) {
        ordered_json out = ordered_json::array();
        for (std::size_t i = 0; i < fresh.size(); ++i)
            out.push_back(arrangeLike(
                fresh[i], layout.is_array() && i < layout.size() ? layout[i] : ordered_json()));
        return out;
    }
    // A number the file wrote as 50 and the writer as 50.0 is the same value: the file's stays.
    if (fresh.is_number() && layout.is_number() && fresh.get<double>() == layout.get<double>())
        return layout;
    return ordered_json::parse(fresh.dump());
}

} // namespace kinstab
