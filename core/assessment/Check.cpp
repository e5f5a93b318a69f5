// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/assessment/Check.h"

#include "core/base/NameTable.h"

#include "core/codes/Verdict.h"

#include <iomanip>
#include <locale>
#include <sstream>

namespace kinstab {

// CheckBasis's names, in its declaration order (Sine, Record, Floors, Planar, Risk, Block).
constexpr std::array<const char*, 6> kCheckBasisNames = {"sine",   "record", "floors",
                                                         "planar", "risk",   "block"};
static_assert(kCheckBasisNames.size() == static_cast<std::size_t>(CheckBasis::Block) + 1);

std::string checkBasisName(CheckBasis b) {
    return enumName(kCheckBasisNames, b);
}

// CheckLevel's names, in its declaration order (Design, MceR, Collapse).
constexpr std::array<const char*, 3> kCheckLevelNames = {"design", "mce_r", "collapse"};
static_assert(kCheckLevelNames.size() == static_cast<std::size_t>(CheckLevel::Collapse) + 1);

std::string checkLevelName(CheckLevel l) {
    return enumName(kCheckLevelNames, l);
}

void settleComparisons(Check& c) {
    c.holds = true;
    c.governingComparison = 0;
    for (std::size_t k = 0; k < c.comparisons.size(); ++k) {
        const Comparison& x = c.comparisons[k];
        c.holds = c.holds && x.holds();
        const Comparison& g = c.comparisons[c.governingComparison];
        if (!x.holds() && (g.holds() || x.orderingMargin() < g.orderingMargin()))
            c.governingComparison = k;
    }
}

double Comparison::orderingMargin() const {
    if (margin) return *margin;
    return demand > 0 ? searchLimit / demand : searchLimit;
}

std::string marginText(const Comparison& x) {
    std::ostringstream s;
    s.imbue(std::locale::classic());
    s << std::fixed << std::setprecision(2) << x.orderingMargin();
    return x.margin ? s.str() : "> " + s.str();
}

std::string quantityText(const Comparison& x, double value) {
    std::ostringstream s;
    s.imbue(std::locale::classic());
    if (x.unit == kAnnualRateUnit)
        s << std::scientific << std::setprecision(2) << value;
    else
        s << std::fixed << std::setprecision(3) << value;
    return s.str();
}

bool Comparison::holds() const {
    return slabHolds(demand, capacity, searchLimit);
}

} // namespace kinstab
