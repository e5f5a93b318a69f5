// SPDX-License-Identifier: GPL-3.0-or-later
#include "report/ComparisonTable.h"

#include "report/ReportSections.h"

namespace kinstab::report {

void addComparisonTable(ReportDocument& doc, const Assessment& s, CheckBasis basis,
                        std::vector<double> columnWeights) {
    Table t{{"check", "compares", "demand (g)", "capacity (g)", "margin", "verdict"},
            {},
            std::move(columnWeights),
            {Align::Left, Align::Left, Align::Right, Align::Right, Align::Right, Align::Left},
            {}};
    for (const Check& c : s.checks) {
        if (c.basis != basis) continue;
        for (std::size_t k = 0; k < c.comparisons.size(); ++k) {
            const Comparison& x = c.comparisons[k];
            const bool governs = k == c.governingComparison;
            if (governs) t.boldRows.push_back(static_cast<int>(t.rows.size()));
            t.rows.push_back({k == 0 ? qs(c.id) : QString(), qs(x.intensity), num(x.demand, 3),
                              num(x.capacity, 3, QStringLiteral("none")), qs(marginText(x)),
                              governs ? qs(c.verdict) : QString()});
        }
    }
    doc.addTable(t);
}

} // namespace kinstab::report
