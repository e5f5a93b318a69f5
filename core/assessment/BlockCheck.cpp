// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/assessment/BlockCheck.h"

#include "core/base/SignificantDigits.h"
#include "core/building/FloorAnalysis.h"
#include "core/io/Project.h"
#include "core/rocking/OverturningAmplitude.h"
#include "core/rocking/RockingMotions.h"

#include <algorithm>
#include <cmath>
#include <locale>
#include <sstream>

namespace kinstab {

namespace {

std::string g(double x) {
    return significantDigits(x, 4);
}

// The search over the level's peak: the project's own limit and scan step (check.max_amplitude,
// check.scan_step, as the slab's searches), each change bisected to the core's relative
// tolerance (core/rocking/OverturningAmplitude.h). Rocking near its threshold is chaotic: thin
// overturning intervals lie between standing amplitudes (a 0.075 x 0.45 m block on the example's
// roof stands at 0.200 and 0.225 g and falls at 0.205-0.224 g), so the scan is no coarser than
// the slab's.
OverturningSearch blockSearch(const Project& p) {
    OverturningSearch s;
    s.maxAmplitude = p.critical.to;
    const double points = std::ceil(p.critical.to / p.critical.scanStep - 1e-9);
    s.scanPoints = static_cast<int>(std::clamp(points, 2.0, 100000.0));
    return s;
}

BlockCheckPart searchBlock(const Project& p, const FreeBlock& b, const Accelerogram& ground,
                           const SweepControl* control) {
    BlockCheckPart part;
    part.block = b;
    part.stories = p.building.stories;
    part.level = freeBlockLevel(b, p.building.stories);
    FloorSettings s = p.floors.value_or(FloorSettings{});
    s.slabLevel = part.level;
    part.demands = floorDemands(p.building, p.codes, s);
    const Accelerogram motion = levelMotion(p.building, s.stiffness, s.damping, part.level, ground);
    part.pga = std::abs(ground.peak().value);
    part.floorPeak = std::abs(motion.peak().value);
    const OverturningSearch search = blockSearch(p);
    part.searchLimit = search.maxAmplitude;
    const OverturningIntervals iv =
        overturningIntervals(freeBlockModel(b), recordFamily(motion), search, control);
    part.intervals = iv.intervals;
    part.runs = iv.runs;
    part.criticalFloorPeak = iv.critical();
    if (part.criticalFloorPeak && part.floorPeak > 0)
        part.criticalPga = *part.criticalFloorPeak * part.pga / part.floorPeak;
    return part;
}

std::string levelSuffix(const FloorDemand& d) {
    if (d.code == "asce7_22_mce") return "asce7_22.mce_r";
    if (d.code == "asce7_22") return "asce7_22.design";
    return d.code;
}

Check blockCheck(const BlockCheckPart& f, const FloorDemand& d, const std::string& recordName) {
    Check c;
    c.basis = CheckBasis::Block;
    c.code = d.code == "asce7_22_mce" ? "asce7_22" : d.code;
    c.codeTitle = d.title;
    c.level = d.code == "asce7_22_mce" ? CheckLevel::MceR : CheckLevel::Design;
    c.id = blockCheckPrefix(f.block) + "." + levelSuffix(d);
    c.model = "free-standing block '" + f.block.name + "', " + blockModelText(f.block) +
              ", on level " + std::to_string(f.level) + " of " + std::to_string(f.stories) +
              " of the shear-building model";
    c.excitation = "ground record " + recordName + " through the building to level " +
                   std::to_string(f.level) + ", scaled to the code level's ground motion";
    const std::string level = "level " + std::to_string(f.level);
    Comparison ground;
    ground.intensity = "ground PGA";
    ground.unit = "g";
    ground.demandName = d.groundPgaSource;
    ground.demand = d.groundPga;
    ground.capacityName = "critical ground PGA, block '" + f.block.name + "' on " + level;
    ground.capacity = f.criticalPga;
    ground.searchLimit = f.floorPeak > 0 ? f.searchLimit * f.pga / f.floorPeak : 0;
    if (ground.capacity && ground.demand > 0) ground.margin = *ground.capacity / ground.demand;
    Comparison formula;
    formula.intensity = "floor peak acceleration, " + level;
    formula.unit = "g";
    formula.demandName = "PFA of " + d.title;
    formula.demand = d.slabPfa;
    formula.capacityName = "critical floor peak, block '" + f.block.name + "' on " + level;
    formula.capacity = f.criticalFloorPeak;
    formula.searchLimit = f.searchLimit;
    if (formula.capacity && formula.demand > 0) formula.margin = *formula.capacity / formula.demand;
    c.comparisons = {ground, formula};
    settleComparisons(c);
    const std::string at =
        c.level == CheckLevel::MceR ? "at the MCE_R level" : "at the design level";
    c.verdict = (c.holds ? "block stays standing " : "block overturns ") + at;
    return c;
}

} // namespace

std::vector<BlockCheckPart> blockCheckParts(const Project& p, const Accelerogram& ground,
                                            const SweepControl* control) {
    std::vector<BlockCheckPart> out;
    for (const FreeBlock& b : p.blocks) {
        if (control && control->isCancelled()) break;
        out.push_back(searchBlock(p, b, ground, control));
    }
    return out;
}

std::vector<Check> blockChecks(const BlockCheckPart& part, const std::string& recordName) {
    std::vector<Check> out;
    for (const FloorDemand& d : part.demands)
        out.push_back(blockCheck(part, d, recordName));
    return out;
}

std::string blockCheckPrefix(const FreeBlock& b) {
    return checkBasisName(CheckBasis::Block) + "." + b.name;
}

std::string blockModelText(const FreeBlock& b) {
    const double alpha = blockAlpha(b.block);
    const double eta = b.restitution.value_or(housnerRestitution(alpha));
    return "b = " + g(b.block.halfWidth) + " m, h = " + g(b.block.halfHeight) +
           " m (alpha = " + g(alpha) + " rad, p = " + g(blockFrequency(b.block)) + " rad/s), " +
           (b.mu ? "mu = " + g(*b.mu) : std::string("no sliding")) + ", " +
           (b.restitution ? "restitution " : "Housner's restitution ") + g(eta) +
           ", exact equations (Housner 1963; Zhang & Makris 2001)";
}

} // namespace kinstab
