// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/risk/SetRisk.h"

#include <map>

namespace kinstab {

SetRisk setRisk(const HazardCurve& c, const std::vector<StudyRow>& rows, const RiskSettings& s,
                const BootstrapSettings& b) {
    BootstrapSettings fitOnly = b;
    fitOnly.resamples = 0; // the resamples are drawn once, below
    SetRisk out;
    out.fragility = fragilityOf(rows, fitOnly);
    const std::optional<LognormalFit>& fit = out.fragility.fit;
    if (!fit) return out;
    const CollapseFragility f{fit->median, fit->beta};
    out.risk = analyzeRisk(c, f, s);
    if (b.resamples > 0) out.bootstrap = riskBootstrap(c, fragilityResamples(rows, b), s.years);
    out.integrand = riskIntegrand(c, f);
    if (out.risk->integral.lambdaC > 0.0) out.margin = s.targetRate / out.risk->integral.lambdaC;
    return out;
}

std::vector<SetRisk> studySetRisks(const HazardCurve& c, const std::vector<StudyRow>& rows,
                                   const RiskSettings& s, const BootstrapSettings& b,
                                   const SweepControl* control) {
    std::map<std::size_t, std::vector<StudyRow>> bySet;
    for (const StudyRow& r : rows)
        bySet[r.set].push_back(r);
    std::vector<SetRisk> out;
    for (const auto& [set, setRows] : bySet) {
        if (control && control->isCancelled()) break;
        out.push_back(setRisk(c, setRows, s, b));
        if (control && control->onProgress) control->onProgress(out.size(), bySet.size());
    }
    return out;
}

} // namespace kinstab
