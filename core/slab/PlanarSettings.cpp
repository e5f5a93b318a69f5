// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/slab/PlanarSettings.h"

#include "core/base/InputError.h"
#include "core/codes/Building.h"
#include "core/excitation/RecordedMotion.h"
#include "core/slab/SlabInputs.h"

namespace kinstab {

std::string verticalSourceName(VerticalSource v) {
    switch (v) {
    case VerticalSource::None:
        return "none";
    case VerticalSource::Rsn68Up:
        return "rsn68_up";
    case VerticalSource::File:
        return "file";
    }
    return "none";
}

std::optional<VerticalSource> verticalSourceFromName(const std::string& name) {
    for (VerticalSource v : {VerticalSource::None, VerticalSource::Rsn68Up, VerticalSource::File})
        if (verticalSourceName(v) == name) return v;
    return std::nullopt;
}

std::string validatePlanarSettings(const PlanarSettings& s) {
    // The planar inputs' own declarations (core/slab/SlabInputs.h); the file calls fy fy_hz.
    if (const InputProblem p = checkInput(kFyInput, s.fyHz); !p.empty())
        return describeAs(p, "planar.fy_hz");
    if (const InputProblem p = checkInput(kAyRatioInput, s.ayRatio); !p.empty())
        return describe(p, "planar.");
    if (const InputProblem p = checkInput(kThetaInput, s.theta); !p.empty())
        return describe(p, "planar.");
    if (s.vertical == VerticalSource::File && s.verticalPath.empty())
        return "planar.vertical.file = '': name the vertical record file";
    return {};
}

std::shared_ptr<const Excitation1D> verticalMotion(const Accelerogram& record, double tstar) {
    return verticalMotion(record, tstar, "planar.vertical " + record.sourceFile);
}

std::shared_ptr<const Excitation1D> verticalMotion(const Accelerogram& record, double tstar,
                                                   const std::string& field) {
    const std::string e = validateRecordedMotion(record, tstar, std::nullopt);
    if (!e.empty()) throw InputError(field + ": " + e);
    return std::make_shared<RecordedMotion>(record, tstar);
}

PlanarCase planarCaseFrom(const Slab1DCase& common, const PlanarSettings& s,
                          std::shared_ptr<const Excitation1D> vertical) {
    if (const std::string e = validatePlanarSettings(s); !e.empty()) throw InputError(e);
    PlanarCase c;
    c.common = common;
    c.theta = s.theta;
    c.ayRatio = s.ayRatio;
    c.fyHz = s.fyHz;
    c.normalization = s.normalization;
    c.vertical = std::move(vertical);
    if (const std::string e = validatePlanarCase(c); !e.empty()) throw InputError("planar: " + e);
    return c;
}

} // namespace kinstab
