// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The planar model's inputs a project keeps (docs/user-guide.md "model (1-DOF / planar)"; Furgerson
// 1980 ch. VI): what a PlanarCase needs beyond the 1-DOF slab case (envelope, t*, mu, limit,
// scale), with the vertical motion named by its source rather than loaded. Reading the record is
// the caller's job (the shipped RSN68 UP lives in the application's resources).

#include "core/excitation/Excitation1D.h"
#include "core/records/Accelerogram.h"
#include "core/slab/PlanarCase.h"
#include "core/slab/Slab1DCase.h"

#include <memory>
#include <optional>
#include <string>

namespace kinstab {

// none: gravity only; rsn68_up: the shipped 1971 San Fernando vertical (NGA RSN68 UP), the
// stand-in for the paper's Pacoima Dam vertical (resources/records/README.md); file: any record.
enum class VerticalSource { None, Rsn68Up, File };
std::string verticalSourceName(VerticalSource v); // "none" | "rsn68_up" | "file"
std::optional<VerticalSource> verticalSourceFromName(const std::string& name);
inline constexpr const char* kRsn68UpFileName = "RSN68_SFERN_PEL-UP.AT2";

struct PlanarSettings {
    double fyHz = 1.0;    // frequency along the walls (the paper: 0.2, 0.5, 1, 2, 5, 10 Hz)
    double ayRatio = 0.9; // A_y / A_x (the paper: Pacoima Dam's ratio of horizontal peaks)
    double theta = 20.0;  // along-wall limit: 2 wall length / wall width
    PlanarNormalization normalization = PlanarNormalization::Product;
    VerticalSource vertical = VerticalSource::Rsn68Up;
    std::string verticalPath; // the record file when vertical == File

    bool operator==(const PlanarSettings&) const = default;
};

// Empty when fine, else "planar.fy_hz = -1 Hz: must be > 0 and at most 1000".
std::string validatePlanarSettings(const PlanarSettings& s);

// The upward base acceleration a_z (g) of a vertical record, from its first sample at tau = 0.
// Throws InputError naming planar.vertical when the record cannot drive the slab.
std::shared_ptr<const Excitation1D> verticalMotion(const Accelerogram& record, double tstar);
// The same, naming the record as field in the message ("--vertical FILE", "vertical='FILE'").
std::shared_ptr<const Excitation1D> verticalMotion(const Accelerogram& record, double tstar,
                                                   const std::string& field);

// The planar case of a project: the 1-DOF case's common inputs plus the settings; vertical is
// null for gravity only. Throws InputError on bad settings or a bad combined case.
PlanarCase planarCaseFrom(const Slab1DCase& common, const PlanarSettings& s,
                          std::shared_ptr<const Excitation1D> vertical);

} // namespace kinstab
