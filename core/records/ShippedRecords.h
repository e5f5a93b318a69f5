// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Records the programs carry inside them, so that a command can read them without Qt's resource
// system or an installed data folder (issue 34: kinstab-cli loads no Qt). Their text is compiled
// in from resources/records/ at build time (core/CMakeLists.txt writes ShippedRecordsText.cpp).

#include <string_view>

namespace kinstab {

// The shipped vertical record: the 1971 San Fernando vertical (NGA RSN68 UP), the stand-in for
// Furgerson's Pacoima Dam vertical (resources/records/README.md). Its name as a source in
// messages (the path the GUI's resources give it) and the note every label and the report show
// with it; its file name is kRsn68UpFileName, beside the project setting that names it
// (core/slab/PlanarSettings.h).
inline constexpr const char* kRsn68UpSource = ":/records/RSN68_SFERN_PEL-UP.AT2";
inline constexpr const char* kRsn68UpNote =
    "Vertical motion: 1971 San Fernando, LA Hollywood Storage FF, UP (NGA RSN68) stands in for the "
    "paper's Pacoima Dam vertical, which is not publicly available.";

// The text of a shipped record by its file name (e.g. "RSN68_SFERN_PEL-UP.AT2"); empty when
// no record of that name is shipped.
std::string_view shippedRecordText(std::string_view fileName);

} // namespace kinstab
