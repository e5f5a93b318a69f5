// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/io/RecordMetricsJson.h"

#include "core/io/JsonValue.h"

namespace kinstab {

nlohmann::json recordMetricsJson(const RecordMetrics& m) {
    nlohmann::json j = {{"pga_g", m.pga},
                        {"pgv_m_s", m.pgv},
                        {"pgd_m", m.pgd},
                        {"final_velocity_m_s", m.finalVelocity},
                        {"baseline_correction", "none"},
                        {"arias_m_s", m.arias},
                        {"t5_s", orNull(m.t5)},
                        {"t95_s", orNull(m.t95)},
                        {"d5_95_s", orNull(m.d5_95)},
                        {"mean_period_s", orNull(m.meanPeriod)},
                        {"sa_period_s", nullptr},
                        {"sa_damping", kSpectralDamping},
                        {"sa_g", nullptr}};
    if (m.sa) {
        j["sa_period_s"] = m.sa->period;
        j["sa_damping"] = m.sa->damping;
        j["sa_g"] = m.sa->g;
    }
    return j;
}

} // namespace kinstab
