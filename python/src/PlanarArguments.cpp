// SPDX-License-Identifier: GPL-3.0-or-later
#include "python/src/PlanarArguments.h"
#include "core/codes/Building.h"
#include "core/excitation/FrequencyRange.h"

#include "core/excitation/RecordedMotion.h"
#include "core/records/RecordReader.h"
#include "core/slab/PlanarSettings.h"
#include "python/src/Arguments.h"

namespace kinstab::python {

namespace {
std::shared_ptr<const Excitation1D> verticalFromFile(const std::string& path, double tstar) {
    Accelerogram record;
    try {
        record = readRecord(path);
    } catch (const RecordError& e) {
        badArgument("vertical='" + path + "': " + e.what());
    }
    try {
        return verticalMotion(record, tstar, "vertical='" + path + "'");
    } catch (const InputError& e) {
        badArgument(e.what());
    }
}
} // namespace

PlanarCase planarCaseFrom(const Slab1DCase& common, const PlanarArguments& a) {
    if (common.solver == SolverKind::Paper)
        badArgument("solver='paper': the paper's RK4 solver is for the 1-DOF model only");
    PlanarCase c = planarCaseSharing(common);
    c.ayRatio = finite("ay_ratio", a.ayRatio);
    if (!(c.ayRatio >= 0.0 && c.ayRatio <= 100.0))
        badArgument("ay_ratio", c.ayRatio, "A_y / A_x must be between 0 and 100");
    c.fyHz = finite("fy", a.fy);
    if (const std::string e = frequencyRangeError(c.fyHz); !e.empty()) badArgument("fy", c.fyHz, e);
    c.slab.theta = finite("theta", a.theta);
    if (!(c.slab.theta > 0.0 && c.slab.theta <= 1e6))
        badArgument("theta", c.slab.theta, "must be > 0 (2 wall length / wall width)");
    c.normalization =
        *normalizationFromName(choice("normalization", a.normalization, "envelope|product"));
    if (a.vertical) c.vertical = verticalFromFile(*a.vertical, c.tstar);
    const std::string e = validatePlanarCase(c);
    if (!e.empty()) badArgument(e);
    return c;
}

} // namespace kinstab::python
