// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/rocking/RockingMotions.h"

#include "core/building/FloorMotions.h"
#include "core/building/ModalModel.h"
#include "core/building/ShearBuilding.h"
#include "core/excitation/EnvelopedSine.h"
#include "core/excitation/RecordedMotion.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace kinstab {

namespace {

// Physical time is the excitations' tau with t* = 1 s: the rocking solver works in seconds.
constexpr double kUnitTime = 1.0;

// The first tau (doubling, then bisected to 1e-6 relative) after which |a| stays below level.
double quietAfter(const Excitation1D& e, double level) {
    double hi = 1.0;
    for (int i = 0; i < 80 && e.boundAfter(hi) > level; ++i)
        hi *= 2.0;
    double lo = 0.0;
    for (int i = 0; i < 60 && hi - lo > 1e-6 * hi; ++i) {
        const double mid = 0.5 * (lo + hi);
        (e.boundAfter(mid) > level ? lo : hi) = mid;
    }
    return hi;
}

std::shared_ptr<const RecordedMotion> recorded(const Accelerogram& a, std::optional<double> peak,
                                               const std::string& what) {
    if (const std::string e = validateRecordedMotion(a, kUnitTime, peak); !e.empty())
        throw std::invalid_argument(what + ": " + e);
    return std::make_shared<RecordedMotion>(a, kUnitTime, peak);
}

} // namespace

std::unique_ptr<BaseMotion> envelopedSineMotion(const Envelope& e, double amplitudeG,
                                                double frequencyHz, std::optional<double> endS) {
    if (const std::string m = validateEnvelopedSine(amplitudeG, frequencyHz, kUnitTime); !m.empty())
        throw std::invalid_argument(m);
    auto sine = std::make_shared<EnvelopedSine>(e, amplitudeG, frequencyHz, kUnitTime);
    const double end = endS ? *endS : quietAfter(*sine, 1e-4 * amplitudeG) * kUnitTime;
    return std::make_unique<ExcitationMotion>(sine, kUnitTime, end);
}

std::unique_ptr<BaseMotion> recordMotion(const Accelerogram& horizontal,
                                         std::optional<double> targetPeak,
                                         const Accelerogram* vertical) {
    auto h = recorded(horizontal, targetPeak, "record");
    std::shared_ptr<const RecordedMotion> v;
    double end = h->endTau();
    if (vertical) {
        std::optional<double> peakV;
        if (targetPeak) {
            const double peakH = std::abs(horizontal.peak().value);
            peakV = peakH > 0.0 ? std::abs(vertical->peak().value) * *targetPeak / peakH : 0.0;
        }
        v = recorded(*vertical, peakV, "vertical record");
        end = std::max(end, v->endTau());
    }
    return std::make_unique<ExcitationMotion>(h, kUnitTime, end * kUnitTime, v);
}

MotionFamily pulseFamily(const Pulse& pulse) {
    return [pulse](double amplitude) -> std::unique_ptr<BaseMotion> {
        Pulse p = pulse;
        p.amplitude = pulse.amplitude < 0.0 ? -amplitude : amplitude;
        return std::make_unique<PulseMotion>(p);
    };
}

MotionFamily recordFamily(const Accelerogram& horizontal, std::optional<Accelerogram> vertical) {
    return [horizontal, vertical](double amplitude) {
        return recordMotion(horizontal, amplitude, vertical ? &*vertical : nullptr);
    };
}

Accelerogram levelMotion(const Building& b, StiffnessProfile profile, double damping, int level,
                         const Accelerogram& ground) {
    if (level == 0) return ground;
    if (level < 0 || level > b.stories)
        throw std::invalid_argument("level = " + std::to_string(level) +
                                    ": must be between 0 (the ground) and " +
                                    std::to_string(b.stories) + " (the roof)");
    const ModalModel model = modalModel(shearBuilding(b, profile));
    FloorMotionOptions o;
    o.damping = damping;
    std::vector<Accelerogram> motions = floorMotions(model, ground, o);
    return motions.at(static_cast<std::size_t>(level - 1));
}

} // namespace kinstab
