// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Every JSON object kinstab writes (kinstab-cli, the GUI's export) names the kinstab version that
// wrote it, so a result file kept in a design folder says which program produced it.

#include <nlohmann/json.hpp>

#include <string>

namespace kinstab {

// j with "kinstab_version" added, dumped (indent < 0: one line), without a trailing newline. The
// one place the version is stamped: a sorted object gets it among its keys, an ordered one
// (the fragility and risk reports, whose key order is their reading order) last.
std::string jsonText(nlohmann::json j, int indent = -1);
std::string jsonText(nlohmann::ordered_json j, int indent = -1);

} // namespace kinstab
