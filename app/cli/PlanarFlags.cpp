// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli/PlanarFlags.h"

#include "app/cli/ModelFlags.h"
#include "core/codes/Building.h"
#include "core/excitation/RecordedMotion.h"
#include "core/records/RecordReader.h"
#include "core/slab/PlanarSettings.h"
#include "core/slab/SlabInputs.h"

namespace kinstab::cli {

bool isPlanar(const Args& args) {
    return modelFromFlags(args) == ModelKind::Planar;
}

namespace {
// The vertical record: upward acceleration in g, from its first sample at tau = 0.
std::shared_ptr<const Excitation1D> verticalFromFile(const std::string& path, double tstar) {
    Accelerogram record;
    try {
        record = readRecord(path);
    } catch (const RecordError& e) {
        throw UsageError("--vertical " + path + ": " + e.what());
    }
    try {
        return verticalMotion(record, tstar, "--vertical " + path);
    } catch (const InputError& e) {
        throw UsageError(e.what());
    }
}
} // namespace

PlanarCase planarCaseFromFlags(const Args& args, bool recordDriven) {
    if (args.text("solver", "exact") == "paper" || args.has("paper-steps"))
        throw UsageError("--solver paper: the paper's RK4 solver is for --model slab1d only");
    for (const char* f : {"record", "floor-period", "damping"})
        if (args.has(f) && !recordDriven)
            throw UsageError(std::string("--") + f + ": not available with --model planar");
    PlanarCase c;
    c.common = commonCaseFromFlags(args);
    c.ayRatio = args.input(kAyRatioInput);
    if (!args.has("fy") && !recordDriven)
        throw UsageError("--fy is required with --model planar (frequency along the walls, Hz; "
                         "the paper uses 0.2, 0.5, 1, 2, 5, 10)");
    c.fyHz = args.has("fy") ? args.input(kFyInput) : c.fyHz;
    c.theta = args.input(kThetaInput);
    c.normalization =
        *normalizationFromName(args.choice("normalization", {"product", "envelope"}, "product"));
    if (args.has("vertical")) c.vertical = verticalFromFile(args.text("vertical"), c.common.tstar);
    args.refuse(checkPlanarCase(c));
    return c;
}

} // namespace kinstab::cli
