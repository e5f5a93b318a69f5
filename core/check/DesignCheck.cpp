// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/check/DesignCheck.h"

#include "core/base/InputLimits.h"
#include "core/base/TextInput.h"
#include "core/codes/Building.h"
#include "core/sweep/Sweep.h"

#include <cmath>
#include <map>
#include <sstream>

namespace kinstab {

std::string validateCriticalSearch(const CriticalSearch& s, const std::string& prefix) {
    return describe(checkCriticalSearch(s), prefix);
}

CodeVerdict judgeCode(const CodeResult& r, std::optional<double> aCrit, double searchLimit) {
    CodeVerdict v;
    v.code = r.code;
    v.title = r.title;
    v.ratio = r.topRatio;
    v.ratioWithoutFt = r.topRatioWithoutFt;
    v.periodSeconds = r.periodSeconds;
    v.frequencyHz = 1.0 / r.periodSeconds;
    v.aCrit = aCrit;
    // Chapter V: below A_crit (or the search limit when nothing collapses) the members
    // overstress first.
    v.verdict = verdictOf(r.topRatio, aCrit, searchLimit);
    std::ostringstream s;
    if (!aCrit) {
        s << "no collapse up to A = " << searchLimit << " g at f = " << v.frequencyHz << " Hz";
    } else {
        if (r.topRatio > 0) v.margin = *aCrit / r.topRatio;
        s << "F_top/w_top = " << r.topRatio << (r.topRatio < *aCrit ? " < " : " >= ")
          << "A_crit = " << *aCrit << " g at f = " << v.frequencyHz << " Hz";
    }
    v.explanation = s.str();
    return v;
}

DesignCheckResult designCheck(const std::vector<CodeResult>& codes, const Slab1DCase& slab,
                              const CriticalSearch& search) {
    return designCheck(codes, slab, search, slab1DPoint(slab));
}

DesignCheckResult designCheck(const std::vector<CodeResult>& codes, const Slab1DCase& slab,
                              const CriticalSearch& search, const PointFunction& point,
                              std::optional<double> scanFrom) {
    if (const std::string e = validateCase(slab); !e.empty()) throw InputError(e);
    if (const std::string e = validateCriticalSearch(search); !e.empty()) throw InputError(e);
    DesignCheckResult out;
    std::map<double, std::optional<double>> cache; // A_crit by frequency
    for (const CodeResult& r : codes) {
        if (!(r.periodSeconds > 0) || !std::isfinite(r.periodSeconds))
            throw InputError(r.code + ".period_s = " + formatDouble(r.periodSeconds) +
                             ": must be > 0");
        const double f = 1.0 / r.periodSeconds;
        auto it = cache.find(f);
        if (it == cache.end()) {
            const CriticalResult c =
                criticalAmplitude(point, f, scanFrom.value_or(slab.slab.mu), search);
            out.runs += c.runs;
            it = cache.emplace(f, c.amplitude).first;
        }
        out.codes.push_back(judgeCode(r, it->second, search.to));
    }
    return out;
}

} // namespace kinstab
