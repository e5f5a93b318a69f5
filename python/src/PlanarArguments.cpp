// SPDX-License-Identifier: GPL-3.0-or-later
#include "python/src/PlanarArguments.h"
#include "core/codes/Building.h"

#include "core/excitation/RecordedMotion.h"
#include "core/records/RecordReader.h"
#include "core/slab/PlanarSettings.h"
#include "core/slab/SlabInputs.h"
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
    PlanarCase c;
    c.common = common;
    c.ayRatio = keyword(kAyRatioInput, a.ayRatio);
    c.fyHz = keyword(kFyInput, a.fy);
    c.theta = keyword(kThetaInput, a.theta);
    c.normalization =
        *normalizationFromName(choice("normalization", a.normalization, "envelope|product"));
    if (a.vertical) c.vertical = verticalFromFile(*a.vertical, c.common.tstar);
    refuse(checkPlanarCase(c));
    return c;
}

} // namespace kinstab::python
