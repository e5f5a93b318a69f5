// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/building/FloorAnalysis.h"

#include "core/base/TextInput.h"
#include "core/check/DesignCheck.h"
#include "core/codes/Asce7FloorDemand.h"
#include "core/codes/Ec8FloorDemand.h"
#include "core/excitation/FloorFilter.h"
#include "core/excitation/RecordedMotion.h"
#include "core/sweep/Sweep.h"

#include <cmath>
#include <stdexcept>

namespace kinstab {

std::string validateFloorAnalysis(const FloorAnalysisInput& in) {
    if (std::string e = validateBuilding(in.building); !e.empty()) return e;
    // The floor motions filter the record at the building's period: name the building's input.
    if (in.building.period && *in.building.period < kMinFloorPeriodS)
        return "building.period_s = " + formatDouble(*in.building.period) +
               " s: the floor motions need a period of at least " + formatDouble(kMinFloorPeriodS) +
               " s";
    if (std::string e = validateFloorSettings(in.settings, in.building.stories); !e.empty())
        return e;
    if (std::string e = validateCase(in.slab); !e.empty()) return "slab: " + e;
    if (in.slab.solver != SolverKind::Exact)
        return "slab.solver = paper: only the exact solver runs recorded motions";
    if (std::string e = validateRecordedMotion(in.ground, in.slab.tstar, std::nullopt); !e.empty())
        return "record: " + e;
    if (in.ground.peak().value == 0.0) return "record: all samples are zero";
    if (in.critical) return validateCriticalSearch(in.search);
    return {};
}

std::vector<FloorDemand> floorDemands(const Building& b, const CodeSelection& codes,
                                      const FloorSettings& s) {
    const int level = s.slabLevel.value_or(b.stories);
    std::vector<FloorDemand> d;
    if (codes.asce7_22) {
        d.push_back(asce7FloorDemand(b, *codes.asce7_22, s.omega0, level, false));
        d.push_back(asce7FloorDemand(b, *codes.asce7_22, s.omega0, level, true));
    }
    if (codes.ec8) d.push_back(ec8FloorDemand(b, *codes.ec8, s.ec8ElementPeriod, level));
    return d;
}

FloorAnalysis analyseFloors(const FloorAnalysisInput& in, SweepControl* control) {
    if (const std::string e = validateFloorAnalysis(in); !e.empty()) throw std::invalid_argument(e);
    FloorAnalysis a;
    a.slabLevel = in.settings.slabLevel.value_or(in.building.stories);
    a.damping = in.settings.damping;
    a.building = shearBuilding(in.building, in.settings.stiffness);
    a.model = modalModel(a.building);
    a.motions = floorMotions(a.model, in.ground, {in.settings.damping, std::nullopt});
    a.pfa = peakAccelerations(a.motions);
    a.pga = std::abs(in.ground.peak().value);
    a.demands = floorDemands(in.building, in.codes, in.settings);
    const Accelerogram sdof =
        floorMotion(in.ground, {a.building.period, in.settings.damping, std::nullopt});
    a.sdofRoofPeak = std::abs(sdof.peak().value);
    if (!in.critical) return a;
    a.critical = levelCriticalPga(in.slab, a.motions, a.pga, in.search, control);
    a.cancelled = control && control->isCancelled();
    if (a.cancelled) return a;
    return a;
}

} // namespace kinstab
