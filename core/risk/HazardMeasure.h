// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The intensity measure a hazard curve is given in, as each source spells it: OpenQuake
// ("PGA", "SA(0.2)"), the USGS hazard service ("PGA", "SA0P2") and a study's rows ("pga",
// "sa(1s/5%)"). Hazard curves are 5 %-damped (the convention of both sources), so a study's Sa at
// another damping is another measure. kinstab's fragilities are in g: PGA or Sa(T) only.

#include <optional>
#include <string>

namespace kinstab {

struct HazardMeasure {
    enum class Kind { Unstated, Pga, Sa } kind = Kind::Unstated; // Unstated: a plain CSV
    double periodS = 0;                                          // Sa only
};

// "PGA", "SA(1 s)", or "unstated".
std::string hazardMeasureName(const HazardMeasure& m);
// None: not PGA or SA(T) with a positive finite period.
std::optional<HazardMeasure> measureFromOpenQuake(const std::string& imt); // "SA(0.2)"
std::optional<HazardMeasure> measureFromUsgs(const std::string& imt);      // "SA0P2"
// A study's measure (intensityName, core/study/StudySpec.h); none for Sa at a damping other
// than 5 %, which no hazard source tabulates.
std::optional<HazardMeasure> measureFromStudy(const std::string& name); // "sa(1s/5%)"
// The same kind and, for Sa, periods equal to 1e-9 relative (0.2 and 0.20000 alike).
bool sameMeasure(const HazardMeasure& a, const HazardMeasure& b);

} // namespace kinstab
