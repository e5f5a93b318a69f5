// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One name array per enum (as KDE LabPlot keeps one array of names beside each enum): entry i is
// the name of the enum's value i, in declaration order, so that the name, the reverse lookup and
// the list of choices all read the one array, and a new value is one new entry. The enums so
// named have no explicit values; each array's size is checked against its enum's last value.

#include <array>
#include <cstddef>
#include <optional>
#include <string_view>

namespace kinstab {

template <class E, std::size_t N>
constexpr const char* enumName(const std::array<const char*, N>& names, E e) {
    const auto i = static_cast<std::size_t>(e);
    return i < N ? names[i] : "";
}

template <class E, std::size_t N>
constexpr std::optional<E> enumFromName(const std::array<const char*, N>& names,
                                        std::string_view name) {
    for (std::size_t i = 0; i < N; ++i)
        if (name == names[i]) return static_cast<E>(i);
    return std::nullopt;
}

} // namespace kinstab
