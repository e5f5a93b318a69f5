// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/io/JsonText.h"

namespace kinstab {

std::string jsonText(nlohmann::json j, int indent) {
    if (j.is_object()) j["kinstab_version"] = KINSTAB_VERSION;
    return j.dump(indent);
}

std::string jsonText(nlohmann::ordered_json j, int indent) {
    if (j.is_object()) j["kinstab_version"] = KINSTAB_VERSION;
    return j.dump(indent);
}

} // namespace kinstab
