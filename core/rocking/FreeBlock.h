// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A free-standing block a project names (a parapet, a cabinet, a museum object): its block, its
// friction and restitution, and the level of the building it stands on. The assessment checks
// each one against the code's ground motion (core/assessment/BlockCheck.h); the project file
// stores the list under "blocks" (core/io/BlockJson.h).

#include "core/rocking/RockingModel.h"

#include <optional>
#include <string>
#include <vector>

namespace kinstab {

struct FreeBlock {
    std::string name;                  // letters, digits, '_' and '-': it is part of a check id
    Block block;                       // b, h (m)
    std::optional<double> mu;          // none: the base holds it, it never slides
    std::optional<double> restitution; // none: Housner's 1 - 1.5 sin^2 alpha
    std::optional<int> level;          // 1 .. stories; none: the roof
};

// The level it stands on: its own, else the roof.
int freeBlockLevel(const FreeBlock& b, int stories);

// The rocking model of the block: the exact equations, from rest, until its fate is decided.
RockingModel freeBlockModel(const FreeBlock& b);

// Empty when every block is fine, else "blocks[K].FIELD = VALUE: why" (K from 0) or a repeated
// name.
std::string validateFreeBlocks(const std::vector<FreeBlock>& blocks, int stories);

} // namespace kinstab
