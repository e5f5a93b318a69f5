// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/rocking/FreeBlock.h"

#include "core/base/TextInput.h"

#include <set>

namespace kinstab {

namespace {

bool idSafe(const std::string& s) {
    if (s.empty() || s.size() > 40) return false;
    for (const char c : s)
        if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
              c == '_' || c == '-'))
            return false;
    return true;
}

std::string checkOne(const FreeBlock& b, int stories, const std::string& at) {
    if (!idSafe(b.name))
        return at + "name = " + quotedToken(b.name) +
               ": must be 1 to 40 letters, digits, '_' or '-' (it names the block's checks)";
    if (InputProblem p = checkInput(kHalfWidthInput, b.block.halfWidth); !p.empty())
        return describeAs(p, at + "half_width_m");
    if (InputProblem p = checkInput(kHalfHeightInput, b.block.halfHeight); !p.empty())
        return describeAs(p, at + "half_height_m");
    if (b.mu)
        if (InputProblem p = checkInput(kBlockMuInput, *b.mu); !p.empty())
            return describeAs(p, at + "mu");
    if (b.restitution)
        if (InputProblem p = checkInput(kRestitutionInput, *b.restitution); !p.empty())
            return describeAs(p, at + "restitution");
    if (b.level && (*b.level < 1 || *b.level > stories))
        return at + "level = " + std::to_string(*b.level) + ": must be 1 to " +
               std::to_string(stories) + " (the building's levels; null: the roof)";
    return {};
}

} // namespace

int freeBlockLevel(const FreeBlock& b, int stories) {
    return b.level.value_or(stories);
}

RockingModel freeBlockModel(const FreeBlock& b) {
    RockingModel m;
    m.block = b.block;
    m.mu = b.mu;
    m.restitution = b.restitution;
    return m;
}

std::string validateFreeBlocks(const std::vector<FreeBlock>& blocks, int stories) {
    std::set<std::string> names;
    for (std::size_t k = 0; k < blocks.size(); ++k) {
        const std::string at = "blocks[" + std::to_string(k) + "].";
        if (std::string e = checkOne(blocks[k], stories, at); !e.empty()) return e;
        if (!names.insert(blocks[k].name).second)
            return at + "name = " + quotedToken(blocks[k].name) + ": another block has this name";
    }
    return {};
}

} // namespace kinstab
