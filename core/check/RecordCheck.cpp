// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/check/RecordCheck.h"

#include <sstream>

namespace kinstab {

std::vector<CodeVerdict> recordVerdicts(const std::vector<CodeResult>& codes,
                                        const RecordCriticalScale& critical,
                                        const CriticalSearch& search) {
    std::vector<CodeVerdict> out;
    for (const CodeResult& r : codes) {
        CodeVerdict v = judgeCode(r, critical.peak, search.to);
        std::ostringstream s; // the record's critical peak does not depend on the code's f
        if (critical.peak)
            s << "F_top/w_top = " << r.topRatio << (r.topRatio < *critical.peak ? " < " : " >= ")
              << "critical record peak = " << *critical.peak << " g";
        else
            s << "no collapse up to a record peak of " << search.to << " g";
        v.explanation = s.str();
        out.push_back(v);
    }
    return out;
}

} // namespace kinstab
