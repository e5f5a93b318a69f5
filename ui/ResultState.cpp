// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/ResultState.h"

#include "core/check/RecordCheck.h"

#include <cmath>

namespace kinstab::ui {

InputFingerprint fingerprintOf(const Project& p) {
    nlohmann::json j = projectToJson(p);
    nlohmann::json codes = {{"building", j["building"]}, {"codes", j["codes"]}};
    // The unit system changes only how lengths are shown: no result goes stale with it. The
    // free-standing block's map judges its own inputs (ui/BlockMapView.h): choosing or editing
    // the block leaves the slab's results as they are.
    for (const char* key :
         {"format", "version", "name", "description", "building", "codes", "units", "block_map"})
        j.erase(key);
    return {j.dump(), codes.dump()};
}

std::optional<DesignCheckResult> rejudge(const DesignCheckResult& kept, const CheckSource& basis,
                                         const std::vector<CodeResult>& codes) {
    DesignCheckResult out;
    out.runs = 0; // nothing was run: the kept A_crit is judged against the new ratios
    if (basis.source == CheckSource::Source::Record) {
        if (!basis.recordCritical) return std::nullopt;
        out.codes = recordVerdicts(codes, *basis.recordCritical, basis.search);
        return out;
    }
    for (const CodeResult& r : codes) {
        if (!(r.periodSeconds > 0)) return std::nullopt;
        const double f = 1.0 / r.periodSeconds;
        const CodeVerdict* found = nullptr;
        for (const CodeVerdict& v : kept.codes)
            if (std::abs(v.frequencyHz - f) <= 1e-12 * f) found = &v;
        if (!found) return std::nullopt; // the building frequency moved: A_crit needs a search
        out.codes.push_back(judgeCode(r, found->aCrit, basis.searchLimit));
    }
    return out;
}

void ResultState::clear() {
    m_pending = Run::None;
    m_surface.reset();
    m_picked.reset();
    m_pickedPlanar.reset();
    m_check.reset();
    m_record.reset();
    m_surfaceKey.clear();
    m_recordKey.clear();
    m_checkKey = {};
}

bool ResultState::setInputs(const std::optional<InputFingerprint>& now,
                            const std::vector<CodeResult>& codes) {
    m_now = now;
    if (!now || !m_check || m_checkKey.sweep != now->sweep || m_checkKey.codes == now->codes)
        return false;
    const std::optional<DesignCheckResult> again = rejudge(*m_check, m_basis, codes);
    if (!again) return false;
    m_check = *again;
    m_checkKey.codes = now->codes;
    return true;
}

void ResultState::startSweep(const Slab1DCase& c, const std::optional<PlanarInputs>& planar) {
    m_runKey = m_now.value_or(InputFingerprint{});
    m_pending = Run::Sweep;
    m_surface = SurfaceResult{c, planar, {}, {}, {}};
    m_surfaceKey = m_runKey.sweep;
    m_picked.reset();
    m_pickedPlanar.reset();
    m_check.reset();
}

void ResultState::setSweepProgress(const SweepResult& r, const GammaGrid& g) {
    if (!m_surface) return;
    m_surface->sweep = r;
    m_surface->gamma = g;
}

void ResultState::setACrit(std::vector<std::pair<double, double>> aCrit) {
    if (m_surface) m_surface->aCrit = std::move(aCrit);
}

void ResultState::setCheck(const DesignCheckResult& check, const CheckSource& basis) {
    m_check = check;
    m_basis = basis;
    m_checkKey = m_runKey;
}

void ResultState::setPicked(std::optional<PointRun> run, std::optional<PlanarPointRun> planar) {
    m_picked = std::move(run);
    m_pickedPlanar = std::move(planar);
}

void ResultState::startRecordRun() {
    m_runKey = m_now.value_or(InputFingerprint{});
    m_pending = Run::Record;
    m_record.reset();
    m_check.reset();
    m_picked.reset(); // the history chart shows the record's run from now on
    m_pickedPlanar.reset();
}

void ResultState::setRecordRun(const RecordOutput& out) {
    m_record = out;
    m_recordKey = m_runKey.sweep;
}

bool ResultState::surfaceStale() const {
    return m_surface && (!m_now || m_surfaceKey != m_now->sweep);
}

bool ResultState::checkStale() const {
    return m_check && (!m_now || !(m_checkKey == *m_now));
}

bool ResultState::recordStale() const {
    return m_record && (!m_now || m_recordKey != m_now->sweep);
}

} // namespace kinstab::ui
