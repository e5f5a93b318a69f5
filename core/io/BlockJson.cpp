// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/io/BlockJson.h"

#include "core/io/JsonValue.h"

namespace kinstab {

using nlohmann::json;

namespace {

// A project lists a handful of blocks; the bound keeps a hostile file from asking for millions
// of overturning searches.
constexpr std::size_t kMaxBlocks = 100;

} // namespace

json freeBlocksToJson(const std::vector<FreeBlock>& blocks) {
    json a = json::array();
    for (const FreeBlock& b : blocks)
        a.push_back({{"name", b.name},
                     {"half_width_m", b.block.halfWidth},
                     {"half_height_m", b.block.halfHeight},
                     {"mu", orNull(b.mu)},
                     {"restitution", orNull(b.restitution)},
                     {"level", orNull(b.level)}});
    return a;
}

std::vector<FreeBlock> freeBlocksFromJson(const JsonReader& project) {
    const json& list = project.raw("blocks");
    if (!list.is_array()) project.fail("blocks", "must be a list of blocks");
    if (list.size() > kMaxBlocks)
        project.fail("blocks", std::to_string(list.size()) + " blocks: at most " +
                                   std::to_string(kMaxBlocks));
    std::vector<FreeBlock> out;
    for (std::size_t k = 0; k < list.size(); ++k) {
        const JsonReader r(list[k], project.field("blocks") + "[" + std::to_string(k) + "]");
        FreeBlock b;
        b.name = r.text("name", "");
        b.block.halfWidth = r.requiredNumber("half_width_m");
        b.block.halfHeight = r.requiredNumber("half_height_m");
        b.mu = r.optionalNumber("mu");
        b.restitution = r.optionalNumber("restitution");
        b.level = r.optionalInteger("level");
        out.push_back(std::move(b));
    }
    return out;
}

} // namespace kinstab
