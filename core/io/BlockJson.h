// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The "blocks" list of a project: the free-standing blocks its assessment checks
// (core/rocking/FreeBlock.h), each
//   {"name": "parapet", "half_width_m": 0.1, "half_height_m": 0.6,
//    "mu": null | 0.6, "restitution": null | 0.9, "level": null | 1..stories}
// mu null or absent: the base holds the block (no sliding); restitution null: Housner's;
// level null: the roof.

#include "core/io/JsonReader.h"
#include "core/rocking/FreeBlock.h"

#include <nlohmann/json.hpp>
#include <vector>

namespace kinstab {

nlohmann::json freeBlocksToJson(const std::vector<FreeBlock>& blocks);
// Throws JsonFieldError naming "blocks[K].FIELD"; ranges are validateFreeBlocks's.
std::vector<FreeBlock> freeBlocksFromJson(const JsonReader& project);

} // namespace kinstab
