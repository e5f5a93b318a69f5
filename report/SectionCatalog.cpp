// SPDX-License-Identifier: GPL-3.0-or-later
#include "report/SectionCatalog.h"

#include "core/base/TextInput.h"

#include "report/ReportError.h"
#include "report/ReportSections.h"

#include <sstream>

namespace kinstab::report {

namespace {

// A new section (a study, a further check) is one row here and one add function.
constexpr SectionEntry kSections[] = {
    {"assumptions", "Assumptions and limitations", true, addAssumptionsSection},
    {"symbols", "Symbols", true, addSymbolTable},
    {"inputs", "Inputs", true, addInputSections},
    {"codes", "Building codes: top-floor force ratio", true, addCodeSections},
    {"excitation", "Excitation (enveloped sine)", true, addExcitationSection},
    {"record", "Recorded excitation", true, addRecordSection},
    {"floors", "Floor motion", true, addFloorsSection},
    {"blocks", "Free-standing blocks: rocking and overturning", true, addBlocksSection},
    {"surface", "γc surface, A_crit(f) and slice", true, addSurfaceSections},
    {"check", "Design check: which failure governs", true, addCheckSection},
    {"study", "Study: collapse fragility over a record suite", true, addStudySection},
    {"risk", "Risk: annual rate of the slab falling", true, addRiskSection},
    {"numerics", "Appendix: numerics", true, addNumericsSection},
    {"references", "References", true, addReferences},
};

} // namespace

std::span<const SectionEntry> sectionCatalog() {
    return kSections;
}

SectionSet defaultSections() {
    SectionSet s;
    for (const SectionEntry& e : kSections)
        if (e.byDefault) s.insert(e.key);
    return s;
}

SectionSet allSections() {
    SectionSet s;
    for (const SectionEntry& e : kSections)
        s.insert(e.key);
    return s;
}

std::string sectionKeyList() {
    std::string out;
    for (const SectionEntry& e : kSections)
        out += (out.empty() ? "" : ", ") + std::string(e.key);
    return out;
}

SectionSet parseSections(const std::string& list) {
    const std::string whole = trimmed(list);
    if (whole == "all") return allSections();
    if (whole == "default") return defaultSections();
    const SectionSet known = allSections();
    SectionSet s;
    std::istringstream in(list);
    std::string key;
    while (std::getline(in, key, ',')) {
        key = trimmed(key);
        if (key.empty()) continue;
        if (!known.count(key))
            throw ReportError("'" + key.substr(0, 40) + "' is not a report section (one of: " +
                              sectionKeyList() + ", or all, default)");
        s.insert(key);
    }
    if (s.empty()) throw ReportError("no section named (one of: " + sectionKeyList() + ")");
    return s;
}

} // namespace kinstab::report
