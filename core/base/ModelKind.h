// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Which slab model a run uses: the paper's one-degree-of-freedom slab (Furgerson 1980, ch. IV) or
// the planar two-degree-of-freedom slab (docs/theory.md §5). Its name in project files, CLI flags,
// JSON results and the Python module is written here and nowhere else.

#include <array>
#include <optional>
#include <string>
#include <string_view>

namespace kinstab {

enum class ModelKind { Slab1D, Planar };

inline constexpr std::array<ModelKind, 2> kModelKinds = {ModelKind::Slab1D, ModelKind::Planar};

// "slab1d" | "planar"
inline constexpr const char* modelKindName(ModelKind m) {
    return m == ModelKind::Planar ? "planar" : "slab1d";
}

// nullopt for any other text; the caller names the field or flag in its message.
inline std::optional<ModelKind> modelKindFromName(std::string_view name) {
    for (ModelKind m : kModelKinds)
        if (name == modelKindName(m)) return m;
    return std::nullopt;
}

// "slab1d or planar", for messages.
inline std::string modelKindChoices() {
    return std::string(modelKindName(ModelKind::Slab1D)) + " or " +
           modelKindName(ModelKind::Planar);
}

} // namespace kinstab
