// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The assessment's checks of one basis as a table: each comparison on its own row (check,
// compares, demand, capacity, margin), the governing one bold with the check's verdict. The
// floor-motion and the free-standing-block sections show their checks this way.

#include "core/assessment/Assessment.h"
#include "report/ReportDocument.h"

#include <vector>

namespace kinstab::report {

void addComparisonTable(ReportDocument& doc, const Assessment& s, CheckBasis basis,
                        std::vector<double> columnWeights);

} // namespace kinstab::report
