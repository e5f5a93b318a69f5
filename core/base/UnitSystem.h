// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The unit system lengths are shown in: SI (m for the building, mm for details such as a wall's
// width) or US customary (ft, in). A project names the one it is reported in ("units": "si" |
// "us"); the GUI's View → Units shows the same choice. Only what is shown changes: a stored
// value keeps the unit it was entered in, so switching never changes a computed result.

#include <optional>
#include <string>

namespace kinstab {

enum class UnitSystem { SI, US };

// Lengths of the building (m | ft) and of details such as a wall's width (mm | in).
enum class LengthScale { Structure, Detail };

inline constexpr double kMetresPerFoot = 0.3048; // exact by definition (1959)
inline constexpr double kMetresPerInch = 0.0254;

inline constexpr double metresPerUnit(UnitSystem s, LengthScale scale) {
    if (s == UnitSystem::US)
        return scale == LengthScale::Structure ? kMetresPerFoot : kMetresPerInch;
    return scale == LengthScale::Structure ? 1.0 : 0.001;
}

// "m", "mm", "ft", "in".
std::string lengthUnitSymbol(UnitSystem s, LengthScale scale);
// Decimals a length is shown with: to a millimetre (m: 3), 0.1 mm for details, or 0.01 ft / in.
int lengthDecimals(UnitSystem s, LengthScale scale);
// metres shown in s at scale, with lengthDecimals and without trailing zeros ("192.2", "7.57").
std::string lengthText(double metres, UnitSystem s, LengthScale scale);

std::string unitSystemName(UnitSystem s); // "si" | "us", as a project file writes it
std::optional<UnitSystem> unitSystemFromName(const std::string& name);

} // namespace kinstab
