// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/io/StudySpecJson.h"

#include "core/base/DisplayText.h"
#include "core/base/InputLimits.h"
#include "core/base/TextInput.h"
#include "core/building/ShearBuilding.h"
#include "core/check/DesignCheck.h"
#include "core/excitation/FloorFilter.h"
#include "core/io/CodesJson.h"
#include "core/io/FloorsJson.h"
#include "core/io/JsonReader.h"
#include "core/io/StudyBlockJson.h"
#include "core/slab/Slab1DCase.h"
#include "core/slab/SlabInputs.h"
#include "core/study/StudyCase.h"

#include <fnmatch.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace kinstab {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// "FIELD = VALUE: why", the form every project field error takes.
[[noreturn]] void badValue(const JsonReader& r, const std::string& key, const std::string& value,
                           const std::string& why) {
    throw JsonFieldError(r.field(key) + " = " + value + ": " + why);
}

std::vector<std::string> patterns(const JsonReader& r, const std::string& key,
                                  const std::string& fallback) {
    if (!r.has(key)) return fallback.empty() ? std::vector<std::string>{} : std::vector{fallback};
    const json& a = r.raw(key);
    if (!a.is_array()) r.fail(key, "expected an array of file-name patterns");
    std::vector<std::string> out;
    for (const json& p : a) {
        if (!p.is_string()) r.fail(key, "expected an array of file-name patterns");
        if (p.get<std::string>().find('\0') != std::string::npos)
            r.fail(key, "a pattern contains a NUL character");
        out.push_back(p.get<std::string>());
    }
    return out;
}

bool matchesAny(const std::vector<std::string>& globs, const std::string& name) {
    return std::any_of(globs.begin(), globs.end(), [&](const std::string& g) {
        return fnmatch(g.c_str(), name.c_str(), 0) == 0;
    });
}

// The record's path as the study file writes it: under a folder, the folder as written joined with
// the file's name; an absolute path stays absolute, a relative one relative to the study file.
std::string labelFor(const fs::path& file, const fs::path& folder, const std::string& given) {
    const fs::path written(given);
    if (file == folder) return written.lexically_normal().generic_string();
    return (written / file.lexically_relative(folder)).lexically_normal().generic_string();
}

// Whether `file` (canonical) lies in `folder` (canonical).
bool inside(const fs::path& file, const fs::path& folder) {
    const fs::path rel = file.lexically_relative(folder);
    return !rel.empty() && *rel.begin() != "..";
}

// A folder entry whose name matched: a regular file, or a symlink to one in the same folder
// (a link out of the folder or one that cannot be followed is refused, naming it).
bool isRecordFile(const fs::directory_entry& entry, const fs::path& folder, const JsonReader& r) {
    std::error_code ec;
    if (!fs::is_symlink(entry.symlink_status(ec))) return entry.is_regular_file(ec);
    const fs::path to = fs::canonical(entry.path(), ec);
    const std::string name = quotedToken(entry.path().filename().string());
    if (ec)
        badValue(r, "path", name,
                 "a symlink that cannot be followed (" + ec.message() + "); exclude it");
    if (!inside(to, folder))
        badValue(r, "path", name,
                 "a symlink out of the folder, to " + to.string() +
                     "; name that file or its folder in the study, or exclude the link");
    return fs::is_regular_file(to, ec);
}

// A folder's files whose names match include and none of exclude, sorted by name so that
// every machine expands the same folder to the same list. An excluded entry is never looked
// at (a self-looping symlink among them does no harm).
std::vector<fs::path> folderFiles(const fs::path& dir, const JsonReader& r) {
    const auto include = patterns(r, "include", "*");
    const auto exclude = patterns(r, "exclude", "");
    std::error_code ec;
    const fs::path real = fs::canonical(dir, ec);
    fs::directory_iterator it(dir, ec);
    if (ec) badValue(r, "path", quotedToken(dir.string()), "cannot be listed: " + ec.message());
    std::vector<fs::path> files;
    // One pass per folder entry (bounded by the folder), at most kMaxStudyRecords + 1 kept.
    for (; it != fs::directory_iterator(); it.increment(ec)) {
        const std::string name = it->path().filename().string();
        if (!matchesAny(include, name) || matchesAny(exclude, name)) continue;
        if (!isRecordFile(*it, real, r)) continue;
        files.push_back(it->path());
        if (files.size() > kMaxStudyRecords) break;
    }
    if (ec) badValue(r, "path", quotedToken(dir.string()), "cannot be listed: " + ec.message());
    std::sort(files.begin(), files.end());
    return files;
}

// records[k].scale: a number in (0, kMaxStudyRecordScale], 1 when absent.
double recordScale(const JsonReader& r) {
    if (!r.has("scale")) return 1.0;
    const json& v = r.raw("scale");
    const double x = v.is_number() ? v.get<double>() : std::nan("");
    if (!(x > 0.0 && x <= kMaxStudyRecordScale))
        badValue(r, "scale",
                 v.is_number()   ? formatDouble(x)
                 : v.is_string() ? quotedToken(v.get<std::string>())
                                 : v.dump(),
                 "must be a number > 0 and at most " + formatDouble(kMaxStudyRecordScale));
    return x;
}

void addRecords(const JsonReader& r, const std::string& baseDir, StudySpec& s) {
    const double scale = recordScale(r);
    s.asGiven = s.asGiven || r.has("scale");
    const std::string given = r.pathText("path", "");
    if (given.empty()) r.fail("path", "missing: a record file or a folder of records");
    fs::path path(given);
    if (path.is_relative() && !baseDir.empty()) path = fs::path(baseDir) / path;
    path = fs::absolute(path).lexically_normal();
    std::error_code ec;
    std::vector<fs::path> files;
    if (fs::is_directory(path, ec))
        files = folderFiles(path, r);
    else if (fs::is_regular_file(path, ec))
        files.push_back(path);
    else
        badValue(r, "path", quotedToken(given), "no such file or folder");
    if (files.empty()) badValue(r, "path", quotedToken(given), "no record file matches");
    for (const fs::path& f : files) {
        StudyRecord record;
        record.file = f.string();
        record.label = labelFor(f, path, given);
        record.scale = scale;
        s.records.push_back(std::move(record));
        if (s.records.size() > kMaxStudyRecords)
            r.fail("path", "more than the limit of " + std::to_string(kMaxStudyRecords) +
                               " records in one study");
    }
}

void readRecords(const JsonReader& top, const std::string& baseDir, StudySpec& s) {
    const json& list = top.raw("records");
    if (!list.is_array() || list.empty())
        top.fail("records", "expected a non-empty array of {\"path\": FILE or FOLDER}");
    for (std::size_t i = 0; i < list.size(); ++i)
        addRecords(JsonReader(list[i], top.field("records") + "[" + std::to_string(i) + "]"),
                   baseDir, s);
}

IntensityMeasure readIntensity(const JsonReader& top) {
    IntensityMeasure im;
    const auto r = top.optionalObject("intensity");
    if (!r) return im;
    const std::string m = r->text("measure", "pga");
    if (m != "pga" && m != "sa") badValue(*r, "measure", quotedToken(m), "must be pga or sa");
    if (m == "pga") return im;
    im.kind = IntensityMeasure::Kind::Sa;
    im.period = r->requiredNumber("period_s");
    im.damping = r->number("damping", im.damping);
    if (!(im.period >= 0.01 && im.period <= 20.0))
        badValue(*r, "period_s", formatDouble(im.period), "must be between 0.01 and 20 s");
    if (!(im.damping > 0.0 && im.damping < 1.0))
        badValue(*r, "damping", formatDouble(im.damping), "must be > 0 and < 1");
    return im;
}

// A list under key (fallback when the key is absent) of at most kMaxStudyListValues values,
// each of which problem(x) finds fine (empty) or says why not.
template <class Problem>
std::vector<double> checkedList(const JsonReader& r, const std::string& key,
                                std::vector<double> fallback, const Problem& problem) {
    if (!r.has(key)) return fallback;
    const std::vector<double> v = r.numbers(key);
    if (v.empty()) r.fail(key, "the list is empty");
    if (v.size() > kMaxStudyListValues)
        r.fail(key, std::to_string(v.size()) + " values, more than the limit of " +
                        std::to_string(kMaxStudyListValues));
    for (std::size_t i = 0; i < v.size(); ++i)
        if (const std::string why = problem(v[i]); !why.empty())
            badValue(r, key + "[" + std::to_string(i) + "]", formatDouble(v[i]), why);
    return v;
}

// A list of positive numbers in (0, max].
std::vector<double> positiveList(const JsonReader& r, const std::string& key, double max,
                                 std::vector<double> fallback) {
    return checkedList(r, key, std::move(fallback), [max](double x) {
        return x > 0.0 && x <= max ? std::string() : "must be > 0 and at most " + formatDouble(max);
    });
}

// A list of a declared input (core/base/NumberInput.h): each value in the input's range.
std::vector<double> inputList(const JsonReader& r, const NumberInput& in,
                              std::vector<double> fallback) {
    return checkedList(r, std::string(in.key), std::move(fallback),
                       [&in](double x) { return checkInput(in, x).why; });
}

void readFloors(const JsonReader& p, StudySpec& s) {
    s.floors = {std::nullopt};
    const auto f = p.optionalObject("floor_filter");
    if (!f) return;
    const auto periods = positiveList(*f, "periods_s", 20.0, {});
    const auto dampings = positiveList(*f, "dampings", 0.99, {0.02});
    if (periods.empty()) f->fail("periods_s", "missing: the floor periods to cross");
    s.floors.clear();
    if (f->boolean("include_ground", false)) s.floors.push_back(std::nullopt);
    for (double t : periods)
        for (double z : dampings) {
            FloorFilterParams check{t, z, std::nullopt};
            if (const InputProblem e = checkFloorFilter(check); !e.empty())
                f->fail(e.key == "damping" ? "dampings" : "periods_s", e.why);
            s.floors.push_back(FloorFilterChoice{t, z});
        }
}

// "building": a project's building object; "floors": a project's floors object (stiffness
// profile and modal damping; the slab's level is what parameters.levels crosses).
void readBuilding(const JsonReader& top, StudySpec& s) {
    const auto b = top.optionalObject("building");
    if (!b) {
        if (top.has("floors")) top.fail("floors", "needs a \"building\" to apply to");
        return;
    }
    StudyBuilding sb;
    sb.building = buildingFromJson(*b);
    if (const auto f = top.optionalObject("floors")) {
        sb.settings = floorSettingsFromJson(*f);
        if (sb.settings.slabLevel) f->fail("slab_level", "a study crosses parameters.levels");
    }
    if (const std::string e = validateFloorSettings(sb.settings, sb.building.stories); !e.empty())
        throw StudyError(e);
    sb.model = modalModel(shearBuilding(sb.building, sb.settings.stiffness));
    s.building = std::move(sb);
}

// parameters.levels: whole numbers 1..stories of the study's building.
void readLevels(const JsonReader& r, StudySpec& s) {
    if (!r.has("levels")) return;
    if (!s.building) r.fail("levels", "needs the study's \"building\"");
    const int stories = s.building->building.stories;
    const std::vector<double> v = r.numbers("levels");
    if (v.empty() || v.size() > kMaxStudyListValues)
        r.fail("levels", "expected 1 to " + std::to_string(kMaxStudyListValues) + " levels");
    for (std::size_t i = 0; i < v.size(); ++i) {
        if (!(v[i] >= 1.0 && v[i] <= stories && v[i] == std::floor(v[i])))
            badValue(r, "levels[" + std::to_string(i) + "]", formatDouble(v[i]),
                     "must be a level from 1 to " + std::to_string(stories) + " (the roof)");
        s.levels.push_back(static_cast<int>(v[i]));
    }
}

// parameters.motion: ["record", "fitted_sine"], each at most once.
void readMotions(const JsonReader& r, StudySpec& s) {
    if (!r.has("motion")) return;
    const json& a = r.raw("motion");
    if (!a.is_array() || a.empty() || a.size() > 2)
        r.fail("motion", "expected [\"record\"], [\"fitted_sine\"] or both");
    s.motions.clear();
    s.motionGiven = true;
    for (std::size_t i = 0; i < a.size(); ++i) {
        const std::string key = "motion[" + std::to_string(i) + "]";
        const std::string m = a[i].is_string() ? a[i].get<std::string>() : a[i].dump();
        const std::optional<StudyMotion> kind = motionFromName(m);
        if (!kind) badValue(r, key, quotedToken(m), "must be \"record\" or \"fitted_sine\"");
        if (std::find(s.motions.begin(), s.motions.end(), *kind) != s.motions.end())
            badValue(r, key, quotedToken(m), "appears twice");
        s.motions.push_back(*kind);
    }
}

void readParameters(const JsonReader& top, StudySpec& s) {
    const auto p = top.optionalObject("parameters");
    static const json empty = json::object();
    const JsonReader none(empty, top.field("parameters"));
    const JsonReader& r = p ? *p : none;
    s.mu = inputList(r, kMuInput, {kMuInput.fallback});
    if (r.has("tstar") && r.has("wall_width_in"))
        r.fail("tstar", "tstar and wall_width_in exclude each other");
    s.tstar = inputList(r, kTstarInput, {kTstarInput.fallback});
    if (r.has("wall_width_in")) {
        s.tstar.clear();
        for (double d : inputList(r, kWallWidthInput, {}))
            s.tstar.push_back(tstarFromWallWidthInches(d));
    }
    s.limit = r.input(kLimitInput);
    readFloors(r, s);
    readLevels(r, s);
    // Levels without a floor filter: the levels alone drive the slab (not the ground as well).
    if (!s.levels.empty() && !r.has("floor_filter")) s.floors.clear();
    readMotions(r, s);
}

void readSearch(const JsonReader& top, StudySpec& s) {
    const auto r = top.optionalObject("search");
    if (r) {
        s.search.to = r->number("max_g", s.search.to);
        s.search.scanStep = r->number("scan_step_g", s.search.scanStep);
        s.search.tolerance = r->number("tolerance_g", s.search.tolerance);
    }
    // The search's rules are core's (checkCriticalSearch); the spec spells its keys with _g.
    if (const InputProblem e = checkCriticalSearch(s.search); !e.empty()) {
        const std::string key = e.key == "max_amplitude" ? "max_g" : e.key + "_g";
        throw StudyError(describeAs(e, top.field("search") + "." + key));
    }
}

// "polarity": "normal" (each record as given, the default) or "both" (as given and inverted).
void readPolarity(const JsonReader& top, StudySpec& s) {
    if (!top.has("polarity")) return;
    const json& p = top.raw("polarity");
    const std::string v = p.is_string() ? p.get<std::string>() : p.dump();
    if (v != "normal" && v != "both")
        badValue(top, "polarity", quotedToken(v), "must be \"normal\" or \"both\"");
    s.bothPolarities = v == "both";
}

} // namespace

StudySpec studyFromJsonText(const std::string& text, const std::string& baseDir) {
    try {
        const json j = parseJsonDocument(text, limits::kMaxProjectFileBytes);
        const JsonReader top(j, "");
        const std::string format = top.text("format", "");
        if (format != kStudyFormat)
            badValue(top, "format", quotedToken(format),
                     std::string("must be \"") + kStudyFormat + "\"");
        const int version = top.integer("version", 0);
        if (version != kStudyVersion)
            badValue(top, "version", std::to_string(version),
                     "this kinstab reads version " + std::to_string(kStudyVersion));
        StudySpec s;
        s.name = top.text("name", "");
        // Printed in the report's study section: the project's rules for text it prints.
        if (const std::string e =
                displayTextProblem(s.name, limits::kMaxNameChars, TextLines::Single);
            !e.empty())
            top.fail("name", e);
        readRecords(top, baseDir, s);
        s.intensity = readIntensity(top);
        readBuilding(top, s);
        s.block = studyBlockFromJson(top);
        if (s.block) refuseSlabParameters(top);
        readParameters(top, s);
        readSearch(top, s);
        readPolarity(top, s);
        // Each list is bounded, so the product cannot overflow before this check.
        if (studyCaseCount(s) > kMaxStudyCases)
            throw StudyError("records x parameters: " + std::to_string(studyCaseCount(s)) +
                             " cases, more than the limit of " + std::to_string(kMaxStudyCases));
        return s;
    } catch (const JsonFieldError& e) {
        throw StudyError(e.what());
    } catch (const InputError& e) {
        throw StudyError(e.what());
    } catch (const fs::filesystem_error& e) {
        throw StudyError(std::string("records: ") + e.what());
    }
}

StudySpec loadStudy(const std::string& path) {
    const FileText f = readTextFile(path, limits::kMaxProjectFileBytes);
    if (!f.error.empty()) throw StudyError(path + ": " + f.error);
    const std::string dir = fs::absolute(path).parent_path().string();
    return studyFromJsonText(f.text, dir);
}

} // namespace kinstab
