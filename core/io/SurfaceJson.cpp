// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/io/SurfaceJson.h"

#include "core/io/CaseJson.h"
#include "core/io/ResultJson.h"

namespace kinstab {

namespace {
// Which side each collapse leaves by, rows of amplitudes (null where the slab did not collapse).
nlohmann::json exitSides(const SweepResult& r) {
    const std::size_t nf = r.grid.frequencies.size();
    nlohmann::json sides = nlohmann::json::array();
    for (std::size_t i = 0; i < r.grid.amplitudes.size(); ++i) {
        nlohmann::json row = nlohmann::json::array();
        for (std::size_t k = 0; k < nf; ++k) {
            const std::size_t idx = i * nf + k;
            const PointResult& p = r.points[idx];
            row.push_back(r.done[idx] && p.outcome == Outcome::Collapsed
                              ? nlohmann::json(exitSideName(p.exitSide))
                              : nlohmann::json());
        }
        sides.push_back(row);
    }
    return sides;
}
} // namespace

nlohmann::json surfaceJson(const SweepResult& r, const Slab1DCase& c) {
    nlohmann::json j = sweepJson(r, c.tauRef());
    j.update(slab1DCaseJson(c));
    return j;
}

nlohmann::json surfaceJson(const SweepResult& r, const PlanarCase& c) {
    nlohmann::json j = sweepJson(r, c.tauRef());
    j.update(planarCaseJson(c));
    j["exit_side"] = exitSides(r);
    return j;
}

} // namespace kinstab
