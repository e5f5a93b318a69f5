// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/io/Project.h"

#include "core/base/DisplayText.h"
#include "core/base/InputLimits.h"
#include "core/base/TextInput.h"
#include "core/io/AtomicFile.h"
#include "core/io/BlockJson.h"
#include "core/io/BlockMapJson.h"
#include "core/io/CodesJson.h"
#include "core/io/FloorsJson.h"
#include "core/io/JsonReader.h"
#include "core/io/JsonValue.h"
#include "core/io/MotionJson.h"
#include "core/io/PlanarJson.h"
#include "core/io/ProjectLayout.h"
#include "core/slab/SlabInputs.h"

#include <cmath>
#include <filesystem>

namespace kinstab {

using nlohmann::json;

Project paperExampleProject() {
    Project p;
    p.name = "Furgerson 1980, 16-story building";
    p.description =
        "Chapter V example: 16-story RC frame with shear walls, Southern California "
        "(UBC zone 4), 30 ft or more of soft-to-medium clay; T = 0.05 h_n/sqrt(D) = "
        "0.998 s, taken as 1.0 s by the paper. ASCE 7-22 and EC8 inputs are chosen for a "
        "comparable site (see resources/examples/README.md).";
    p.building.name = "16-story office building";
    p.building.period = 1.0;
    p.codes.ubc1976 = Ubc1976Inputs{};
    p.codes.atc306 = Atc306Inputs{};
    p.codes.asce7_22 = Asce7Inputs{};
    p.codes.ec8 = Eurocode8Inputs{};
    p.grid.amplitudes = linspaceStep(0.70, 1.15, 0.05);
    p.grid.frequencies = linspaceStep(0.5, 1.125, 0.125);
    return p;
}

std::string validateProject(const Project& p) {
    // The texts printed on the report (core/base/DisplayText.h); the description alone may
    // have several lines.
    if (std::string e = checkDisplayText("name", p.name, limits::kMaxNameChars); !e.empty())
        return e;
    if (std::string e = checkDisplayText("building.name", p.building.name, limits::kMaxNameChars);
        !e.empty())
        return e;
    if (std::string e = checkDisplayText("description", p.description, limits::kMaxDescriptionChars,
                                         TextLines::Multiple);
        !e.empty())
        return e;
    if (std::string e = validateProjectInfo(p.info); !e.empty()) return e;
    std::string e = validateBuilding(p.building);
    if (e.empty()) e = validateCodes(p.codes);
    if (e.empty() && !(e = validateCase(p.slab)).empty()) e = "slab: " + e;
    if (e.empty() && p.wallWidthIn)
        e = describe(checkInput(kWallWidthInput, *p.wallWidthIn), "slab.");
    if (e.empty() && (!p.grid.amplitudes.empty() || !p.grid.frequencies.empty()) &&
        !(e = validateGrid(p.grid)).empty())
        e = "grid: " + e;
    if (e.empty()) e = validateCriticalSearch(p.critical);
    if (e.empty()) e = validatePlanarSettings(p.planar);
    if (e.empty() && p.record) e = validateRecordExcitation(*p.record);
    if (e.empty() && p.floors) e = validateFloorSettings(*p.floors, p.building.stories);
    if (e.empty()) e = validateFreeBlocks(p.blocks, p.building.stories);
    if (e.empty()) e = describe(checkBlockMapSettings(p.blockMap), "block_map.");
    return e;
}

namespace {

json slabToJson(const Project& p) {
    const Slab1DCase& c = p.slab;
    json env = c.envelope.preset ? json(presetName(*c.envelope.preset))
                                 : json{{"alpha", c.envelope.alpha}, {"beta", c.envelope.beta}};
    json j = {{"envelope", env},
              {"mu", c.slab.mu},
              {"limit", c.slab.limit},
              {"duration", orNull(c.slab.duration)},
              {"solver", solverName(c.solver)},
              {"paper_steps", c.paperStepsPerPeriod},
              {"scale", tauScaleName(c.scale)}};
    if (p.wallWidthIn)
        j["wall_width_in"] = *p.wallWidthIn;
    else
        j["tstar"] = c.tstar;
    return j;
}

Envelope envelopeFrom(const JsonReader& r) {
    const json& e = r.raw("envelope");
    if (e.is_string()) {
        const auto preset = presetFromName(e.get<std::string>());
        if (!preset)
            r.fail("envelope",
                   quotedToken(e.get<std::string>()) + " must be fast, moderate or slow");
        return Envelope::fromPreset(*preset);
    }
    const JsonReader o(e, r.field("envelope"));
    Envelope env{o.requiredNumber("alpha"), o.requiredNumber("beta"), std::nullopt};
    if (const std::string err = validateEnvelope(env.alpha, env.beta); !err.empty())
        r.fail("envelope", err);
    return env;
}

void slabFrom(const JsonReader& r, Project& p) {
    Slab1DCase& c = p.slab;
    c.envelope = envelopeFrom(r);
    if (r.has("tstar") && r.has("wall_width_in"))
        r.fail("tstar", "tstar and wall_width_in exclude each other");
    p.wallWidthIn = r.optionalInput(kWallWidthInput);
    c.tstar = p.wallWidthIn ? tstarFromWallWidthInches(*p.wallWidthIn) : r.input(kTstarInput);
    c.slab.mu = r.input(kMuInput);
    c.slab.limit = r.input(kLimitInput);
    c.slab.duration = r.optionalInput(kDurationInput);
    const std::string solver = r.text("solver", "exact");
    if (solver != "exact" && solver != "paper")
        r.fail("solver", quotedToken(solver) + " must be exact or paper");
    c.solver = solver == "exact" ? SolverKind::Exact : SolverKind::Paper;
    c.paperStepsPerPeriod = r.input(kPaperStepsInput);
    const std::string scale = r.text("scale", "tau_max");
    const auto s = tauScaleFromName(scale);
    if (!s) r.fail("scale", quotedToken(scale) + " must be tau_max, tau_rise, tau_dur or one");
    c.scale = *s;
    if (const std::string e = validateCase(c); !e.empty()) throw JsonFieldError("slab: " + e);
}

json checkToJson(const CriticalSearch& s) {
    return {{"from", s.from},
            {"max_amplitude", s.to},
            {"scan_step", s.scanStep},
            {"tolerance", s.tolerance}};
}

CriticalSearch checkFrom(const JsonReader& r) {
    CriticalSearch s;
    s.from = r.number("from", s.from);
    s.to = r.number("max_amplitude", s.to);
    s.scanStep = r.number("scan_step", s.scanStep);
    s.tolerance = r.number("tolerance", s.tolerance);
    return s;
}

void checkHeader(const JsonReader& r) {
    const auto format = r.optionalText("format");
    if (format != std::string(kProjectFormat))
        r.fail("format",
               "this is not a kinstab project (expected \"" + std::string(kProjectFormat) + "\")");
    const auto version = r.optionalInteger("version");
    if (!version) r.fail("version", "missing");
    if (*version < 1 || *version > kProjectVersion)
        r.fail("version", std::to_string(*version) + ": this kinstab reads project versions 1 to " +
                              std::to_string(kProjectVersion));
}

} // namespace

json projectToJson(const Project& p, const std::string& baseDir) {
    json j = {{"format", kProjectFormat},
              {"version", kProjectVersion},
              {"name", p.name},
              {"description", p.description},
              {"building", buildingToJson(p.building)},
              {"codes", codesToJson(p.codes)},
              {"slab", slabToJson(p)},
              {"grid", {{"amplitudes", p.grid.amplitudes}, {"frequencies", p.grid.frequencies}}},
              {"model", modelKindName(p.model)},
              {"check", checkToJson(p.critical)}};
    // Blocks for what the project does not use are left out: a 1-DOF project has no planar
    // block (unless it keeps planar inputs of its own), a sine project no excitation block.
    if (p.model == ModelKind::Planar || p.planar != PlanarSettings{})
        j["planar"] = planarSettingsToJson(p.planar, baseDir);
    if (p.record) j["excitation"] = excitationToJson(p.record, baseDir);
    if (p.floors) j["floors"] = floorSettingsToJson(*p.floors);
    if (p.units) j["units"] = unitSystemName(*p.units);
    if (!p.info.empty()) j["info"] = projectInfoToJson(p.info);      // older files have none
    if (p.study) j["study"] = studyToJson(*p.study, baseDir);        // nor a study
    if (!p.blocks.empty()) j["blocks"] = freeBlocksToJson(p.blocks); // nor blocks
    if (p.blockMap != BlockMapSettings{}) j["block_map"] = blockMapToJson(p.blockMap); // nor this
    return j;
}

namespace {
// The order a new file is written in (a file that was read keeps its own).
const nlohmann::ordered_json& newFileOrder() {
    static const nlohmann::ordered_json order = nlohmann::ordered_json::parse(R"({
      "format": 0, "version": 0, "name": 0, "description": 0, "info": 0,
      "building": {"name": 0, "stories": 0, "unit": 0, "height": 0, "plan_dimension": 0,
                   "period_s": 0, "system": 0, "occupancy": 0},
      "codes": {"ubc1976": 0, "atc306": 0, "asce7_22": 0, "ec8": 0},
      "slab": {"envelope": 0, "tstar": 0, "wall_width_in": 0, "mu": 0, "limit": 0},
      "grid": {"amplitudes": 0, "frequencies": 0},
      "model": 0, "check": {"from": 0, "max_amplitude": 0}, "units": 0, "planar": 0,
      "excitation": 0, "floors": 0, "study": 0, "blocks": 0, "block_map": 0})");
    return order;
}
} // namespace

std::string projectText(const Project& p, const std::string& baseDir) {
    return arrangeLike(projectToJson(p, baseDir), p.layout, newFileOrder()).dump(2) + "\n";
}

UnitSystem projectUnits(const Project& p) {
    if (p.units) return *p.units;
    return p.building.unit == LengthUnit::Feet ? UnitSystem::US : UnitSystem::SI;
}

Project projectFromJson(const json& j, const std::string& baseDir) {
    try {
        const JsonReader r(j, "");
        checkHeader(r);
        Project p;
        p.name = r.text("name", "");
        p.description = r.text("description", "");
        if (r.has("info")) p.info = projectInfoFromJson(r.raw("info"));
        p.building = buildingFromJson(r.object("building"));
        if (auto c = r.optionalObject("codes")) p.codes = codesFromJson(*c);
        if (auto s = r.optionalObject("slab")) slabFrom(*s, p);
        if (auto g = r.optionalObject("grid")) {
            p.grid.amplitudes = g->numbers("amplitudes");
            p.grid.frequencies = g->numbers("frequencies");
        }
        const std::string model = r.text("model", modelKindName(ModelKind::Slab1D));
        const std::optional<ModelKind> kind = modelKindFromName(model);
        if (!kind)
            throw ProjectError("model = " + quotedToken(model) + ": must be " + modelKindChoices());
        p.model = *kind;
        // Projects written before the planar model have no "planar" key: defaults.
        if (auto pl = r.optionalObject("planar")) p.planar = planarSettingsFromJson(*pl, baseDir);
        if (auto c = r.optionalObject("check")) p.critical = checkFrom(*c);
        p.record = excitationFromJson(r, baseDir);
        if (auto f = r.optionalObject("floors")) p.floors = floorSettingsFromJson(*f);
        p.study = studyFromJson(r, baseDir);
        if (const auto u = r.optionalText("units")) {
            p.units = unitSystemFromName(*u);
            if (!p.units) r.fail("units", quotedToken(*u) + " must be si or us");
        }
        if (r.has("blocks")) p.blocks = freeBlocksFromJson(r);
        if (auto b = r.optionalObject("block_map")) p.blockMap = blockMapFromJson(*b);
        if (const std::string e = validateProject(p); !e.empty()) throw ProjectError(e);
        if (p.record) checkRecordFile(*p.record);
        if (p.study) checkStudyFile(*p.study);
        return p;
    } catch (const JsonFieldError& e) {
        throw ProjectError(e.what());
    } catch (const InputError& e) {
        throw ProjectError(e.what());
    } catch (const json::exception& e) {
        throw ProjectError(std::string("malformed project: ") + e.what());
    }
}

Project parseProject(const std::string& text, const std::string& baseDir) {
    json j;
    try {
        j = parseJsonDocument(text, limits::kMaxProjectFileBytes);
    } catch (const JsonFieldError& e) {
        throw ProjectError(e.what());
    }
    Project p = projectFromJson(j, baseDir);
    // The same text in its own order (the checks above passed: size, depth, numbers).
    p.layout = nlohmann::ordered_json::parse(text);
    return p;
}

namespace {
std::string directoryOf(const std::string& path) {
    return std::filesystem::absolute(std::filesystem::path(path)).parent_path().string();
}
} // namespace

Project loadProject(const std::string& path) {
    const FileText f = readTextFile(path, limits::kMaxProjectFileBytes);
    if (!f.error.empty()) throw ProjectError(path + ": " + f.error);
    try {
        return parseProject(f.text, directoryOf(path));
    } catch (const ProjectError& e) {
        throw ProjectError(path + ": " + e.what());
    }
}

void saveProject(const Project& p, const std::string& path) {
    if (const std::string e = validateProject(p); !e.empty()) throw ProjectError("not saved: " + e);
    try {
        writeFileAtomically(path, projectText(p, directoryOf(path)));
    } catch (const FileError& e) {
        throw ProjectError(e.what());
    }
}

} // namespace kinstab
