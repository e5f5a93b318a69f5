// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/study/KaplanMeier.h"

#include <algorithm>

namespace kinstab {

std::vector<KaplanMeierStep> kaplanMeier(const CensoredSample& s) {
    std::vector<double> collapsed = s.collapsed, censored = s.censored;
    std::sort(collapsed.begin(), collapsed.end());
    std::sort(censored.begin(), censored.end());
    const auto total = static_cast<double>(collapsed.size() + censored.size());
    std::vector<KaplanMeierStep> steps;
    double survival = 1.0;
    std::size_t censoredBelow = 0;
    // Each pass takes the collapses at one intensity: bounded by the number of collapses.
    for (std::size_t i = 0; i < collapsed.size();) {
        const double t = collapsed[i];
        std::size_t j = i;
        while (j < collapsed.size() && collapsed[j] == t)
            ++j;
        while (censoredBelow < censored.size() && censored[censoredBelow] < t)
            ++censoredBelow;
        const auto atRisk =
            static_cast<double>(collapsed.size() - i + censored.size() - censoredBelow);
        const auto after = atRisk - static_cast<double>(j - i);
        // Before any censoring the product telescopes to (still at risk) / (all records): the
        // fraction (collapses so far) / (all records) is then exact to the last bit.
        if (censoredBelow == 0) {
            survival = after / total;
            steps.push_back({t, (total - after) / total});
        } else {
            survival *= after / atRisk;
            steps.push_back({t, 1.0 - survival});
        }
        i = j;
    }
    return steps;
}

} // namespace kinstab
