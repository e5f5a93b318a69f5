// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The report's four-column table of inputs: quantity (or parameter), symbol, value (right
// aligned) and unit, in widths 3 : 1 : 2 : 1. Every input section starts its table here, so the
// input tables line up page after page.

#include "report/ReportDocument.h"

#include <QString>

namespace kinstab::report {

inline Table quantityTable(const QString& first = QStringLiteral("quantity")) {
    return Table{{first, "symbol", "value", "unit"},
                 {},
                 {3, 1, 2, 1},
                 {Align::Left, Align::Left, Align::Right, Align::Left},
                 {}};
}

} // namespace kinstab::report
