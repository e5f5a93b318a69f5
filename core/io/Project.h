// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A kinstab project: everything an engineer enters once — the building, the codes with their
// own inputs, the 1-DOF slab case, the sweep grid and the model — saved as versioned JSON
// ({"format": "kinstab-project", "version": 1, ...}). Loading validates every field and names
// the bad one ("building.height = -3: must be > 0 ..."); a truncated or corrupt file is a
// ProjectError, never a crash. Saving is atomic (temporary file renamed into place).

#include "core/base/ModelKind.h"
#include "core/base/UnitSystem.h"
#include "core/building/FloorSettings.h"
#include "core/codes/Building.h"
#include "core/codes/CodeSet.h"
#include "core/excitation/RecordExcitation.h"
#include "core/io/ProjectInfo.h"
#include "core/io/StudyJson.h"
#include "core/rocking/BlockMapSettings.h"
#include "core/rocking/FreeBlock.h"
#include "core/slab/PlanarSettings.h"
#include "core/slab/Slab1DCase.h"
#include "core/sweep/CriticalAmplitude.h"
#include "core/sweep/Grid.h"

#include <nlohmann/json.hpp>

#include <optional>
#include <stdexcept>
#include <string>

namespace kinstab {

struct ProjectError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

inline constexpr const char* kProjectFormat = "kinstab-project";
inline constexpr int kProjectVersion = 1;

struct Project {
    std::string name;
    std::string description;
    ProjectInfo info; // engineer, firm, client, revisions: the report's title and signature blocks
    Building building;
    CodeSelection codes;
    Slab1DCase slab;                        // envelope, t*, mu, limit, solver, scale
    std::optional<double> wallWidthIn;      // set when t* comes from the wall width d (inches)
    SweepGrid grid;                         // A (g) and f (Hz) of the γc surface
    ModelKind model = ModelKind::Slab1D;    // written by its name (core/base/ModelKind.h)
    PlanarSettings planar;                  // the planar model's own inputs (core/io/PlanarJson.h)
    CriticalSearch critical;                // A_crit search of the design check
    std::optional<RecordExcitation> record; // a record drives the slab; none: the enveloped sine
    std::optional<FloorSettings> floors;    // the floor-motion check; present: the report shows it
    std::optional<ProjectStudy> study;      // a record-suite study; present: the report shows it
    // The unit system lengths are shown and reported in ("units"); none: the building's (ft: US).
    std::optional<UnitSystem> units;
    // How the file was written, so a save changes only what changed (core/io/ProjectLayout.h):
    // its key order and the grid as typed ("0.70:1.15:0.05"). Empty for a new project.
    nlohmann::ordered_json layout;
    std::vector<FreeBlock> blocks; // free-standing blocks on levels, each a check (with a record)
    // The GUI's free-standing block model and its overturning map ("block_map"); not part of
    // the assessment (the blocks above are).
    BlockMapSettings blockMap;
};

// The project's unit system: as it names it, else US for a building in ft and SI for one in m.
UnitSystem projectUnits(const Project& p);

// The paper's 16-story building (chapter V) with the paper's slab, envelope and grid.
Project paperExampleProject();

std::string validateProject(const Project& p); // empty when fine

// baseDir: the project file's directory; a record's file is stored relative to it and resolved
// against it on load ("" keeps paths as they are). A record file that cannot be read is a
// ProjectError naming excitation.record.file and the path.
nlohmann::json projectToJson(const Project& p, const std::string& baseDir = "");
// The file's text: projectToJson arranged like the file it was read from (p.layout), so a
// save changes only what changed (core/io/ProjectLayout.h); two-space indent, final newline.
std::string projectText(const Project& p, const std::string& baseDir = "");
// Throws ProjectError naming the field.
Project projectFromJson(const nlohmann::json& j, const std::string& baseDir = "");
// Throws ProjectError (also on bad JSON).
Project parseProject(const std::string& text, const std::string& baseDir = "");

Project loadProject(const std::string& path);                // throws ProjectError
void saveProject(const Project& p, const std::string& path); // atomic; throws ProjectError

} // namespace kinstab
