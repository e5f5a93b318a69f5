// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Records the programs carry inside them, so that a command can read them without Qt's resource
// system or an installed data folder (issue 34: kinstab-cli loads no Qt). Their text is compiled
// in from resources/records/ at build time (core/CMakeLists.txt writes ShippedRecordsText.cpp).

#include <string_view>

namespace kinstab {

// The text of a shipped record by its file name (e.g. "RSN68_SFERN_PEL-UP.AT2"); empty when
// no record of that name is shipped.
std::string_view shippedRecordText(std::string_view fileName);

} // namespace kinstab
