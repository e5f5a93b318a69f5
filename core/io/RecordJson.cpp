// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/io/RecordJson.h"

#include "core/base/TextInput.h"
#include "core/excitation/Envelope.h"
#include "core/excitation/EnvelopeFit.h"
#include "core/io/JsonValue.h"
#include "core/io/ResultJson.h"

#include <stdexcept>

namespace kinstab {

nlohmann::json accelerogramJson(const Accelerogram& a) {
    const SignedPeak p = a.peak();
    return {{"file", utf8FromLegacy(a.sourceFile)}, // a file name need not be UTF-8; JSON must be
            {"format", a.format},
            {"name", a.name},
            {"station", a.station},
            {"component", a.component},
            {"npts", a.size()},
            {"dt", a.dt},
            {"duration_s", a.duration()},
            {"file_units", accelUnitName(a.fileUnit)},
            {"peak_g", p.value},
            {"peak_time_s", p.time},
            {"header_peak_g", orNull(a.headerPeak)}};
}

nlohmann::json floorFilterJson(const FloorFilterParams& p) {
    return {{"period_s", p.period}, {"damping", p.damping}, {"tail_s", floorTailSeconds(p)}};
}

nlohmann::json spectrumJson(const AmplitudeSpectrum& s, std::size_t count) {
    nlohmann::json peaks = nlohmann::json::array();
    for (const SpectrumPeak& p : spectrumPeaks(s, count))
        peaks.push_back({{"frequency_hz", p.frequency}, {"amplitude", p.amplitude}});
    return {{"points", s.points}, {"df_hz", s.df}, {"peaks", peaks}};
}

nlohmann::json envelopeFitJson(const Accelerogram& motion) {
    try {
        const EnvelopeFit fit = fitEnvelope(motion);
        // With t* = 1 s the dimensionless times are seconds.
        const CharacteristicTimes t =
            Envelope{fit.alpha, fit.beta, std::nullopt}.computedTimes(1.0);
        return {
            {"alpha", fit.alpha},    {"beta", fit.beta},     {"scale_g", fit.scale},
            {"rms_g", fit.rms},      {"peak_g", fit.peak()}, {"peaks", fit.peaks},
            {"t_rise_s", t.tauRise}, {"t_max_s", t.tauMax},  {"t_dur_s", numberOrNull(t.tauDur)}};
    } catch (const std::invalid_argument& e) {
        return {{"error", e.what()}};
    }
}

nlohmann::json recordFitJson(const RecordAnalysis& a) {
    if (!a.fit) return {{"error", a.fitError}};
    const EnvelopeFit& f = *a.fit;
    return {{"alpha", f.alpha}, {"beta", f.beta},     {"scale_g", f.scale},
            {"rms_g", f.rms},   {"peak_g", f.peak()}, {"peak_time_s", f.peakTime()}};
}

nlohmann::json recordCriticalJson(const RecordAnalysis& a, const CriticalSearch& s) {
    const RecordCriticalScale& c = *a.critical;
    return {{"peak_g", orNull(c.peak)},      {"scale_factor", orNull(c.factor)},
            {"motion_peak_g", c.motionPeak}, {"runs", c.runs},
            {"max_amplitude", s.to},         {"scan_step", s.scanStep},
            {"tolerance", s.tolerance},      {"wall_time_s", a.criticalSeconds}};
}

} // namespace kinstab
