// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The report's optional sections, in report order: the one place a section is registered (its
// key for `kinstab-cli report --sections`, its title for the GUI's export dialog, whether it is
// in the default report, and the function that adds it). The front matter (title block,
// signature block, revisions) and the summary with the verdict are always in the report.

#include "core/io/Project.h"
#include "report/ReportAnalysis.h"
#include "report/ReportDocument.h"

#include <set>
#include <span>
#include <string>

namespace kinstab::report {

using AddSection = void (*)(ReportDocument&, const Project&, const ReportAnalysis&);

struct SectionEntry {
    const char* key;   // "assumptions"
    const char* title; // "Assumptions and limitations"
    bool byDefault;
    AddSection add;
};

using SectionSet = std::set<std::string>;

std::span<const SectionEntry> sectionCatalog();
SectionSet defaultSections();
SectionSet allSections();
// "inputs,codes,references" (comma-separated keys, or "all" / "default"). Throws ReportError
// naming the unknown key and listing the keys there are.
SectionSet parseSections(const std::string& list);
// "assumptions, inputs, codes, ..." : every key, for messages and --help.
std::string sectionKeyList();

} // namespace kinstab::report
