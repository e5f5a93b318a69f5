// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/slab/PlanarSettings.h"

#include "core/codes/Building.h"
#include "core/codes/CodeResult.h"
#include "core/excitation/FrequencyRange.h"
#include "core/excitation/RecordedMotion.h"

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
    try {
        // The same ranges as kinstab-cli's --fy, --ay-ratio and --theta (app/cli/PlanarFlags.cpp).
        requireRange("planar.fy_hz", s.fyHz, kMinFrequencyHz, kMaxFrequencyHz, "Hz");
        requireRange("planar.ay_ratio", s.ayRatio, 0.0, 100.0);
        requireAbove("planar.theta", s.theta, 0.0, 1e6);
    } catch (const InputError& e) {
        return e.what();
    }
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
    PlanarCase c = planarCaseSharing(common);
    c.slab.theta = s.theta;
    c.ayRatio = s.ayRatio;
    c.fyHz = s.fyHz;
    c.normalization = s.normalization;
    c.vertical = std::move(vertical);
    if (const std::string e = validatePlanarCase(c); !e.empty()) throw InputError("planar: " + e);
    return c;
}

} // namespace kinstab
