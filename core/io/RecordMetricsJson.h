// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A record's catalogue numbers (core/excitation/RecordMetrics.h) as JSON, SI units in the keys,
// null where a number does not exist (the duration of a record of zeros).

#include "core/excitation/RecordMetrics.h"

#include <nlohmann/json.hpp>

namespace kinstab {

nlohmann::json recordMetricsJson(const RecordMetrics& m);

} // namespace kinstab
