// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli/BuildingFlags.h"

#include "core/codes/CodeCatalog.h"
#include "core/io/Project.h"

#include <map>

namespace kinstab::cli {

namespace {

struct CodeFlags {
    CodeKey code;
    std::vector<const char*> selectors; // any of these selects the code
    std::vector<const char*> others;    // need a selector
};

const std::vector<CodeFlags>& codeFlags() {
    static const std::vector<CodeFlags> t = {
        {CodeKey::Ubc1976, {"zone"}, {"importance", "k-factor", "site-period"}},
        {CodeKey::Atc306, {"av", "map-area"}, {"aa", "soil", "r"}},
        {CodeKey::Ubc1997,
         {"ubc97-zone"},
         {"ubc97-soil", "na", "nv", "ubc97-importance", "ubc97-r"}},
        {CodeKey::Asce7_22,
         {"sds"},
         {"sd1", "s1", "tl", "site-class", "risk-category", "ie", "asce-r"}},
        {CodeKey::Ec8,
         {"ag"},
         {"ground", "spectrum-type", "importance-class", "gamma-i", "q", "beta"}},
    };
    return t;
}

bool selected(const Args& args, const CodeFlags& c) {
    for (const char* s : c.selectors)
        if (args.has(s)) return true;
    return false;
}

double positive(const Args& args, const std::string& flag) {
    const double v = args.requiredNumber(flag);
    if (v <= 0.0) throw UsageError("--" + flag + " " + args.text(flag) + ": must be > 0");
    return v;
}

} // namespace

std::set<std::string> buildingFlagNames() {
    std::set<std::string> f = {"stories",     "height-ft",     "height-m", "dimension-ft",
                               "dimension-m", "period",        "system",   "occupancy",
                               "weights",     "story-heights", "project"};
    for (const CodeFlags& c : codeFlags()) {
        for (const char* s : c.selectors)
            f.insert(s);
        for (const char* s : c.others)
            f.insert(s);
    }
    return f;
}

std::set<std::string> buildingSwitchNames() {
    return {"irregular"};
}

Building buildingFromFlags(const Args& args) {
    Building b;
    b.stories = args.integer("stories", 0);
    if (!args.has("stories")) throw UsageError("missing required flag --stories");
    if (b.stories < 1 || b.stories > kMaxStories)
        throw UsageError("--stories " + args.text("stories") + ": must be between 1 and " +
                         std::to_string(kMaxStories));
    if (args.has("height-ft") == args.has("height-m"))
        throw UsageError("give exactly one of --height-ft and --height-m");
    if (args.has("dimension-ft") == args.has("dimension-m"))
        throw UsageError("give exactly one of --dimension-ft and --dimension-m");
    const bool feet = args.has("height-ft");
    if (feet != args.has("dimension-ft"))
        throw UsageError("--height-* and --dimension-* must use the same unit (ft or m)");
    b.unit = feet ? LengthUnit::Feet : LengthUnit::Metres;
    b.height = positive(args, feet ? "height-ft" : "height-m");
    b.planDimension = positive(args, feet ? "dimension-ft" : "dimension-m");
    if (args.has("period")) b.period = positive(args, "period");
    const auto systems = systemNames();
    b.system = *systemFromName(args.choice("system", {systems.begin(), systems.end()}, "other"));
    const auto occ = occupancyNames();
    b.occupancy =
        *occupancyFromName(args.choice("occupancy", {occ.begin(), occ.end()}, "standard"));
    if (args.has("weights")) b.storyWeights = args.list("weights");
    if (args.has("story-heights")) b.storyHeights = args.list("story-heights");
    return b;
}

namespace {

Ubc1976Inputs ubc1976Flags(const Args& a) {
    Ubc1976Inputs in;
    in.zone = a.integer("zone", 4);
    if (a.has("importance")) in.importance = a.requiredNumber("importance");
    in.k = a.requiredNumber("k-factor");
    if (a.has("site-period")) in.sitePeriod = a.requiredNumber("site-period");
    return in;
}

Atc306Inputs atcFlags(const Args& a) {
    Atc306Inputs in;
    if (a.has("map-area")) {
        if (a.has("aa") || a.has("av"))
            throw UsageError("--map-area and --aa/--av exclude each other");
        in.mapArea = a.integer("map-area", 7);
        if (*in.mapArea < 1 || *in.mapArea > 7)
            throw UsageError("--map-area " + a.text("map-area") +
                             ": must be between 1 and 7 (ATC 3-06 Table 1-B)");
        in.aa = in.av = atcMapAreaCoefficient(*in.mapArea);
    } else {
        in.av = a.requiredNumber("av");
        in.aa = a.requiredNumber("aa");
    }
    const auto soil = a.optionalText("soil");
    if (!soil) throw UsageError("missing required flag --soil (ATC 3-06 Table 3-A: S1|S2|S3)");
    in.soil = *atcSoilFromName(a.choice("soil", {"S1", "S2", "S3"}, "S2"));
    in.r = a.requiredNumber("r");
    return in;
}

Ubc1997Inputs ubc1997Flags(const Args& a) {
    Ubc1997Inputs in;
    in.zone = *ubc97ZoneFromName(a.choice("ubc97-zone", {"1", "2A", "2B", "3", "4"}, "4"));
    in.soil = *ubc97SoilFromName(a.choice("ubc97-soil", {"SA", "SB", "SC", "SD", "SE"}, "SD"));
    in.na = a.number("na", 1.0);
    in.nv = a.number("nv", 1.0);
    if (a.has("ubc97-importance")) in.importance = a.requiredNumber("ubc97-importance");
    in.r = a.requiredNumber("ubc97-r");
    return in;
}

Asce7Inputs asceFlags(const Args& a) {
    Asce7Inputs in;
    in.sds = a.requiredNumber("sds");
    in.sd1 = a.requiredNumber("sd1");
    if (a.has("s1")) in.s1 = a.requiredNumber("s1");
    in.tl = a.requiredNumber("tl");
    const auto classes = asceSiteClassNames();
    in.siteClass = a.choice("site-class", {classes.begin(), classes.end()}, "Default");
    if (a.has("risk-category")) in.riskCategory = a.integer("risk-category", 2);
    if (a.has("ie")) in.importance = a.requiredNumber("ie");
    in.r = a.requiredNumber("asce-r");
    return in;
}

Eurocode8Inputs ec8Flags(const Args& a) {
    Eurocode8Inputs in;
    in.agr = a.requiredNumber("ag");
    if (!a.has("ground"))
        throw UsageError("missing required flag --ground (EN 1998-1 Table 3.1: A|B|C|D|E)");
    in.ground = *ec8GroundFromName(a.choice("ground", {"A", "B", "C", "D", "E"}, "C"));
    in.spectrumType = a.integer("spectrum-type", 1);
    if (a.has("importance-class")) in.importanceClass = a.integer("importance-class", 2);
    if (a.has("gamma-i")) in.gammaI = a.requiredNumber("gamma-i");
    in.q = a.requiredNumber("q");
    in.beta = a.number("beta", 0.2);
    in.regularInElevation = !a.has("irregular");
    return in;
}

} // namespace

CodeSelection codesFromFlags(const Args& args) {
    for (const CodeFlags& c : codeFlags())
        if (!selected(args, c))
            for (const char* f : c.others)
                if (args.has(f))
                    throw UsageError(std::string("--") + f + " applies to " +
                                     std::string(codeInfo(c.code).shortName) + ", which needs --" +
                                     c.selectors[0]);
    if (args.has("irregular") && !args.has("ag"))
        throw UsageError("--irregular applies to EC8, which needs --ag");
    CodeSelection s;
    if (args.has("zone")) s.ubc1976 = ubc1976Flags(args);
    if (args.has("av") || args.has("map-area")) s.atc306 = atcFlags(args);
    if (args.has("ubc97-zone")) s.ubc1997 = ubc1997Flags(args);
    if (args.has("sds")) s.asce7_22 = asceFlags(args);
    if (args.has("ag")) s.ec8 = ec8Flags(args);
    if (s.empty())
        throw UsageError("no code selected: give --zone (UBC 1976), --av or --map-area (ATC 3-06), "
                         "--ubc97-zone (UBC 1997), --sds (ASCE 7-22) or --ag (EC8)");
    return s;
}

std::string flagForField(const std::string& message) {
    static const std::map<std::string, std::string> t = {
        {"building.stories", "--stories"},
        {"building.height", "--height-ft/--height-m"},
        {"building.plan_dimension", "--dimension-ft/--dimension-m"},
        {"building.period_s", "--period"},
        {"building.story_weights", "--weights"},
        {"building.story_heights", "--story-heights"},
        {"ubc1976.zone", "--zone"},
        {"ubc1976.importance", "--importance"},
        {"ubc1976.k", "--k-factor"},
        {"ubc1976.site_period_s", "--site-period"},
        {"atc306.aa", "--aa"},
        {"atc306.av", "--av"},
        {"atc306.r", "--r"},
        {"atc306.map_area", "--map-area"},
        {"ubc1997.na", "--na"},
        {"ubc1997.nv", "--nv"},
        {"ubc1997.na/nv", "--na/--nv"},
        {"ubc1997.importance", "--ubc97-importance"},
        {"ubc1997.r", "--ubc97-r"},
        {"asce7_22.sds", "--sds"},
        {"asce7_22.sd1", "--sd1"},
        {"asce7_22.s1", "--s1"},
        {"asce7_22.tl", "--tl"},
        {"asce7_22.importance", "--ie"},
        {"asce7_22.r", "--asce-r"},
        {"asce7_22.risk_category", "--risk-category"},
        {"asce7_22.site_class", "--site-class"},
        {"ec8.agr", "--ag"},
        {"ec8.gamma_i", "--gamma-i"},
        {"ec8.q", "--q"},
        {"ec8.beta", "--beta"},
        {"ec8.spectrum_type", "--spectrum-type"},
        {"ec8.importance_class", "--importance-class"},
    };
    const auto end = message.find_first_of(" :[");
    const auto it = t.find(message.substr(0, end));
    return it == t.end() ? std::string() : it->second;
}

// A core validation message, prefixed with the flag that carries the bad field.
UsageError inputUsageError(const InputError& e) {
    const std::string flag = flagForField(e.what());
    return UsageError(flag.empty() ? std::string(e.what()) : flag + ": " + e.what());
}

Project projectFromFlag(const Args& args) {
    try {
        return loadProject(args.text("project"));
    } catch (const ProjectError& e) {
        throw UsageError(std::string("--project ") + e.what());
    }
}

} // namespace kinstab::cli
