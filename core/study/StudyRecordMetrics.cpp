// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/study/StudyRecordMetrics.h"

#include "core/records/RecordReader.h"

namespace kinstab {

std::optional<double> studySaPeriod(const StudySpec& s) {
    if (s.intensity.kind == IntensityMeasure::Kind::Sa) return s.intensity.period;
    for (const std::optional<FloorFilterChoice>& f : s.floors)
        if (f) return f->period;
    return std::nullopt;
}

std::vector<StudyRecordMetrics> studyRecordMetrics(const StudySpec& s) {
    const std::optional<double> period = studySaPeriod(s);
    std::vector<StudyRecordMetrics> out;
    out.reserve(s.records.size());
    for (const StudyRecord& r : s.records) {
        Accelerogram a;
        try {
            a = r.ground ? *r.ground : readRecord(r.file);
        } catch (const RecordError& e) {
            throw StudyError("records: " + std::string(e.what()));
        }
        for (double& x : a.samples)
            x *= r.scale;
        out.push_back({r.label, recordMetrics(a, period)});
    }
    return out;
}

} // namespace kinstab
