// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Reading a hazard curve from the files engineers have (docs/studies.md, "Risk"):
//  - OpenQuake's hazard_curve-*.csv: line 1 a banner holding investigation_time=T and imt='...',
//    line 2 the header lon,lat[,depth],poe-X..., then a row per site of probabilities of
//    exceedance in T years; the annual rate is -ln(1 - PoE) / T (Poisson occurrence).
//  - the USGS hazard service's JSON: response[i].metadata.imt.value (PGA, SA0P2, ...),
//    response[i].metadata.xvalues (g) and response[i].data[0].yvalues (annual rates).
//  - a plain CSV: the header im_g,annual_rate and a row per point; a comment line
//    "# imt=PGA" or "# imt=SA(1.0)" (OpenQuake's spelling) states the measure.
// Numbers are read in the C locale's syntax whatever the process locale. Every problem is a
// HazardError naming the file and the line (or the JSON path) and the value.

#include "core/risk/HazardCurve.h"

#include <optional>
#include <string>

namespace kinstab {

enum class HazardFormat { Auto, OpenQuake, Usgs, Csv };
std::string hazardFormatName(HazardFormat f); // "auto" | "openquake" | "usgs" | "csv"
std::optional<HazardFormat> hazardFormatFromName(const std::string& name);

struct HazardSite {
    double lon = 0, lat = 0; // degrees
};

struct HazardRequest {
    HazardFormat format = HazardFormat::Auto;
    std::optional<HazardSite> site; // OpenQuake: the row of this site; none: the first row
    // The fragility's measure: picks the USGS response, and a file that states another measure
    // is refused naming both. None: the file's own measure (a USGS file must then hold one).
    std::optional<HazardMeasure> measure;
};

// OpenQuake writes five decimals of a degree: a site matches within 1e-4 degrees (about 10 m).
inline constexpr double kHazardSiteToleranceDeg = 1e-4;

// The format of a file's text: '{' first is USGS JSON, a first line starting with '#' and
// naming investigation_time is OpenQuake, anything else the plain CSV.
HazardFormat detectHazardFormat(const std::string& text);

// label: the file's name in messages.
HazardCurve parseHazardText(const std::string& text, const std::string& label,
                            const HazardRequest& request);
HazardCurve readHazardFile(const std::string& path, const HazardRequest& request);

} // namespace kinstab
