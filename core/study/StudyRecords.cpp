// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/study/StudyRecords.h"

#include "core/base/InputLimits.h"
#include "core/base/Sha256.h"
#include "core/base/TextInput.h"
#include "core/building/FloorMotions.h"
#include "core/excitation/FloorFilter.h"
#include "core/records/RecordReader.h"
#include "core/study/StudyFingerprint.h"

#include <algorithm>
#include <cmath>

namespace kinstab {

namespace {

std::string fileBytes(const StudyRecord& r) {
    FileText f = readTextFile(r.file, limits::kMaxRecordFileBytes);
    if (!f.error.empty()) throw StudyError("records: " + r.file + ": " + f.error);
    return std::move(f.text);
}

bool moves(const std::vector<double>& samples) {
    return std::any_of(samples.begin(), samples.end(), [](double x) { return x != 0.0; });
}

// A motion that is zero throughout has no critical scale: refused before any case runs. The
// levels' motions are kept for the cases (r.levelMotions).
void requireMotion(const StudySpec& s, StudyRecord& r, const Accelerogram& ground) {
    for (const auto& f : s.floors) {
        const bool zero =
            f ? !moves(floorMotion(ground, {f->period, f->damping, std::nullopt}).samples)
              : !moves(ground.samples);
        if (zero) throw RecordError(r.file, 0, "the motion is zero throughout");
    }
    if (s.levels.empty()) return;
    std::vector<Accelerogram> levels =
        floorMotions(s.building->model, ground, {s.building->settings.damping, std::nullopt});
    for (const Accelerogram& m : levels)
        if (!moves(m.samples)) throw RecordError(r.file, 0, "the motion is zero throughout");
    // Only the study's levels are kept (a tall building's others would multiply the memory).
    for (std::size_t i = 0; i < levels.size(); ++i)
        if (std::find(s.levels.begin(), s.levels.end(), static_cast<int>(i + 1)) == s.levels.end())
            levels[i].samples = std::vector<double>();
    r.levelMotions = std::make_shared<const std::vector<Accelerogram>>(std::move(levels));
}

} // namespace

void loadStudyRecords(StudySpec& s) {
    std::size_t samples = 0;
    for (StudyRecord& r : s.records) {
        const std::string bytes = fileBytes(r);
        try {
            auto ground = std::make_shared<Accelerogram>(parseRecord(RecordText(bytes, r.file)));
            samples += ground->size();
            if (samples > kMaxStudySuiteSamples)
                throw StudyError("records: " + std::to_string(samples) + " samples up to " +
                                 r.file + ", more than the limit of " +
                                 std::to_string(kMaxStudySuiteSamples) +
                                 " a study holds in memory; split the suite into studies");
            requireMotion(s, r, *ground);
            r.ground = std::move(ground);
        } catch (const RecordError& e) {
            throw StudyError("records: " + std::string(e.what()));
        }
        r.sha256 = sha256Hex(bytes);
    }
    s.fingerprint = studyFingerprint(s);
}

void hashStudyRecords(StudySpec& s) {
    for (StudyRecord& r : s.records)
        r.sha256 = sha256Hex(fileBytes(r));
    s.fingerprint = studyFingerprint(s);
}

} // namespace kinstab
