// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Plain words for what the project stores as keys: the lateral system, the occupancy and every
// code input, each with its symbol and unit, so that no JSON key reaches the report.

#include "core/codes/Building.h"
#include "core/codes/CodeSet.h"
#include "report/ReportDocument.h"

#include <QString>

namespace kinstab::report {

QString systemLabel(StructuralSystem s); // "dual system: moment frame with shear walls"
QString occupancyLabel(Occupancy o);     // "standard (offices, dwellings, commerce)"

// One row per code input: code, input, symbol, value, unit. An input the project leaves open
// reads "from the occupancy" or the like, never "default".
Table codeInputsTable(const CodeSelection& codes);

} // namespace kinstab::report
