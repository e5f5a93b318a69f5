// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/io/ResultTable.h"

#include "core/base/InternalError.h"

#include <cmath>
#include <cstdio>
#include <string>

namespace kinstab {

std::string sweepTable(const SweepResult& r, double tauRef) {
    std::string out;
    char buf[64];
    out += "  A (g) \\ f (Hz)";
    for (double f : r.grid.frequencies) {
        std::snprintf(buf, sizeof buf, " %8.4g", f);
        out += buf;
    }
    out += "\n";
    for (std::size_t i = 0; i < r.grid.amplitudes.size(); ++i) {
        std::snprintf(buf, sizeof buf, "%16.4g", r.grid.amplitudes[i]);
        out += buf;
        for (std::size_t j = 0; j < r.grid.frequencies.size(); ++j) {
            const std::size_t k = i * r.grid.frequencies.size() + j;
            const PointResult& p = r.points[k];
            if (!r.done[k])
                std::snprintf(buf, sizeof buf, " %8s", "-");
            else if (p.outcome == Outcome::Collapsed && !std::isfinite(p.tauC))
                throw InternalError("sweep point A = " + std::to_string(r.grid.amplitudes[i]) +
                                    " g, f = " + std::to_string(r.grid.frequencies[j]) +
                                    " Hz collapsed with no finite tau_c");
            else if (p.outcome == Outcome::Collapsed)
                std::snprintf(buf, sizeof buf, " %8.3f", tauRef / p.tauC);
            else if (p.outcome == Outcome::Stable)
                std::snprintf(buf, sizeof buf, " %8s", ".");
            else
                std::snprintf(buf, sizeof buf, " %8s", outcomeName(p.outcome).c_str());
            out += buf;
        }
        out += "\n";
    }
    return out;
}

} // namespace kinstab
