// SPDX-License-Identifier: GPL-3.0-or-later
// The free-standing block (core/rocking, docs/theory.md §10): one run with the keys of
// kinstab-cli rocking's JSON, the overturning amplitudes of a pulse or a record (rocking
// --critical), and the overturning map over a_p / (alpha g) and omega_p / p (rocking-map) as
// NumPy arrays. Keywords are checked by the inputs core declares (ValueError naming the keyword);
// the searches release the GIL and honour Ctrl+C (python/src/Interruptible.h).

#include "core/rocking/OverturningAmplitude.h"
#include "core/rocking/OverturningMap.h"
#include "core/rocking/RockingMotions.h"
#include "core/rocking/RockingSolver.h"
#include "python/src/Arguments.h"
#include "python/src/Arrays.h"
#include "python/src/Bindings.h"
#include "python/src/Interruptible.h"

#include <pybind11/stl.h>

namespace py = pybind11;

namespace kinstab::python {

namespace {

using Opt = std::optional<double>;

RockingModel modelFrom(double halfWidth, double halfHeight, Opt restitution, bool linear, Opt mu,
                       double initialTilt, Opt duration) {
    RockingModel m;
    m.block.halfWidth = keyword(kHalfWidthInput, halfWidth);
    m.block.halfHeight = keyword(kHalfHeightInput, halfHeight);
    if (restitution) m.restitution = keyword(kRestitutionInput, *restitution);
    m.equations = linear ? RockingEquations::Linearised : RockingEquations::Exact;
    if (mu) m.mu = keyword(kBlockMuInput, *mu);
    m.initialTilt = keyword(kInitialTiltInput, initialTilt);
    if (duration) m.duration = keyword(kRockingDurationInput, *duration);
    refuse(checkRockingModel(m));
    return m;
}

Pulse pulseFrom(const std::string& shape, Opt amplitude, Opt frequency, Opt duration) {
    Pulse p;
    p.shape =
        *pulseShapeFromName(choice("pulse", shape, "half-sine|one-sine|one-cosine|rectangular"));
    if (!amplitude) badArgument("amplitude: a pulse needs its amplitude (g)");
    p.amplitude = keyword(kPulseAmplitudeInput, *amplitude);
    const bool rectangular = p.shape == PulseShape::Rectangular;
    if (rectangular && frequency)
        badArgument("pulse_frequency: a rectangular pulse takes pulse_duration (s)");
    if (!rectangular && duration)
        badArgument("pulse_duration: only a rectangular pulse has one (pulse_frequency, Hz)");
    if (rectangular) {
        if (!duration) badArgument("pulse_duration: a rectangular pulse needs it (s)");
        p.durationS = keyword(kPulseDurationInput, *duration);
    } else {
        if (!frequency) badArgument("pulse_frequency: a " + shape + " pulse needs it (Hz)");
        p.frequencyHz = keyword(kPulseFrequencyInput, *frequency);
    }
    refuse(checkPulse(p));
    return p;
}

// The base motion and the family the critical search scales: a pulse, a record (scaled to
// amplitude, its peak in g, when given), or none (free rocking from initial_tilt).
struct Excitation {
    std::unique_ptr<BaseMotion> motion;
    MotionFamily family;
};

Excitation excitationFrom(const std::optional<std::string>& pulse, const Accelerogram* record,
                          Opt amplitude, Opt frequency, Opt duration) {
    if (pulse && record) badArgument("record: pulse and record exclude each other");
    Excitation e;
    if (pulse) {
        const Pulse p = pulseFrom(*pulse, amplitude, frequency, duration);
        e.motion = std::make_unique<PulseMotion>(p);
        e.family = pulseFamily(p);
        return e;
    }
    if (frequency || duration) badArgument("pulse_frequency: needs pulse=SHAPE");
    if (record) {
        Opt peak;
        if (amplitude) peak = keyword(kPulseAmplitudeInput, *amplitude);
        try {
            e.motion = recordMotion(*record, peak);
        } catch (const std::invalid_argument& x) {
            badArgument(std::string("record: ") + x.what());
        }
        e.family = recordFamily(*record);
        return e;
    }
    if (amplitude) badArgument("amplitude: needs pulse=SHAPE or record=");
    e.motion = std::make_unique<NoMotion>();
    return e;
}

py::dict resultDict(const RockingResult& r, const RockingModel& m) {
    py::dict d;
    d["outcome"] = std::string(rockingOutcomeName(r.outcome));
    d["max_theta_over_alpha"] = r.maxThetaOverAlpha;
    d["impact_times_s"] = toArray(r.impactTimes);
    d["impacts"] = r.impactTimes.size();
    d["overturn_time_s"] = r.overturnTime ? py::object(py::float_(*r.overturnTime)) : py::none();
    d["leaves_base_time_s"] =
        r.leavesBaseTime ? py::object(py::float_(*r.leavesBaseTime)) : py::none();
    d["sliding_displacement_m"] = r.slidingDisplacement;
    d["max_sliding_m"] = r.maxSliding;
    d["end_time_s"] = r.endTime;
    d["steps"] = r.steps;
    d["events"] = r.events;
    d["alpha_rad"] = blockAlpha(m.block);
    d["p_rad_s"] = blockFrequency(m.block);
    d["restitution"] = restitutionOf(m);
    return d;
}

py::dict rocking(double halfWidth, double halfHeight, Opt restitution, bool linear, Opt mu,
                 double initialTilt, Opt duration, const std::optional<std::string>& pulse,
                 const Accelerogram* record, Opt amplitude, Opt frequency, Opt pulseDuration,
                 bool history, double historyStep) {
    const RockingModel m =
        modelFrom(halfWidth, halfHeight, restitution, linear, mu, initialTilt, duration);
    const Excitation e = excitationFrom(pulse, record, amplitude, frequency, pulseDuration);
    if (!pulse && !record && !(m.initialTilt > 0))
        badArgument("pulse: no excitation: give pulse=SHAPE, record=, or initial_tilt > 0 for "
                    "free rocking");
    if (!(historyStep >= 1e-6 && historyStep <= 1e3))
        badArgument("history_step", historyStep, "must be 1e-6 to 1000 s");
    std::vector<RockingSample> h;
    RockingRunOptions o;
    if (history) {
        o.recorder = [&h](const RockingSample& s) { h.push_back(s); };
        o.sampleInterval = historyStep;
    }
    RockingResult r;
    {
        py::gil_scoped_release unlocked;
        r = simulateRocking(m, *e.motion, o);
    }
    py::dict d = resultDict(r, m);
    if (history) {
        d["t_s"] = column<double>(h, [](const RockingSample& s) { return s.t; });
        d["theta_rad"] = column<double>(h, [](const RockingSample& s) { return s.theta; });
        d["omega_rad_s"] = column<double>(h, [](const RockingSample& s) { return s.omega; });
        d["sliding_m"] = column<double>(h, [](const RockingSample& s) { return s.sliding; });
    }
    return d;
}

py::dict rockingCritical(double halfWidth, double halfHeight, Opt restitution, bool linear, Opt mu,
                         const std::optional<std::string>& pulse, const Accelerogram* record,
                         Opt frequency, Opt pulseDuration, double maxAmplitude, int scanPoints,
                         double tolerance) {
    const RockingModel m = modelFrom(halfWidth, halfHeight, restitution, linear, mu, 0.0, {});
    if (!pulse && !record) badArgument("pulse: give pulse=SHAPE or record= to scale");
    // The pulse's own amplitude is what the search scales: 1 g stands in for it.
    const Excitation e =
        excitationFrom(pulse, record, pulse ? Opt(1.0) : Opt(), frequency, pulseDuration);
    OverturningSearch s;
    if (!(maxAmplitude > 0 && maxAmplitude <= 1000))
        badArgument("max_amplitude", maxAmplitude, "must be > 0 and at most 1000 g");
    if (scanPoints < 2 || scanPoints > 100000)
        badArgument("scan_points", scanPoints, "must be 2 to 100000");
    if (!(tolerance >= 1e-12 && tolerance <= 0.1))
        badArgument("tolerance", tolerance, "must be 1e-12 to 0.1");
    s.maxAmplitude = maxAmplitude;
    s.scanPoints = scanPoints;
    s.tolerance = tolerance;
    s.refineDepth = kOverturningRefineDepth; // as kinstab-cli rocking --critical
    s.maxRuns = kOverturningMaxRuns;
    SweepControl control;
    OverturningIntervals iv;
    if (!runWatchingSignals(control, [&] { iv = overturningIntervals(m, e.family, s, &control); }))
        throw py::error_already_set();
    py::dict d;
    const std::optional<double> c = iv.critical();
    d["critical_amplitude_g"] = c ? py::object(py::float_(*c)) : py::none();
    py::list intervals;
    for (const auto& [from, to] : iv.intervals)
        intervals.append(py::make_tuple(from, to));
    d["overturning_intervals_g"] = intervals;
    d["max_amplitude_g"] = maxAmplitude;
    d["critical_runs"] = iv.runs;
    d["critical_run_limit_reached"] = iv.runLimitReached;
    return d;
}

py::dict overturningMapDict(double halfWidth, double halfHeight, Opt restitution, bool linear,
                            Opt mu, const std::string& shape, std::pair<double, double> amplitudes,
                            std::pair<double, double> frequencies, int amplitudePoints,
                            int frequencyPoints, int threads) {
    const RockingModel m = modelFrom(halfWidth, halfHeight, restitution, linear, mu, 0.0, {});
    OverturningMapSpec spec;
    spec.shape =
        *pulseShapeFromName(choice("shape", shape, "half-sine|one-sine|one-cosine|rectangular"));
    spec.amplitudeMin = finite("amplitudes[0]", amplitudes.first);
    spec.amplitudeMax = finite("amplitudes[1]", amplitudes.second);
    spec.frequencyMin = finite("frequencies[0]", frequencies.first);
    spec.frequencyMax = finite("frequencies[1]", frequencies.second);
    if (!(spec.amplitudeMin > 0 && spec.amplitudeMax > spec.amplitudeMin))
        badArgument("amplitudes: must be (low, high) with 0 < low < high (a_p / (alpha g))");
    if (!(spec.frequencyMin > 0 && spec.frequencyMax > spec.frequencyMin))
        badArgument("frequencies: must be (low, high) with 0 < low < high (omega_p / p)");
    if (amplitudePoints < 2 || amplitudePoints > 2049)
        badArgument("amplitude_points", amplitudePoints, "must be 2 to 2049");
    if (frequencyPoints < 2 || frequencyPoints > 2049)
        badArgument("frequency_points", frequencyPoints, "must be 2 to 2049");
    spec.amplitudePoints = amplitudePoints;
    spec.frequencyPoints = frequencyPoints;
    spec.threads = threads;
    SweepControl control;
    OverturningMap map;
    if (!runWatchingSignals(control, [&] { map = overturningMap(m, spec, &control); }))
        throw py::error_already_set();
    const auto nf = static_cast<py::ssize_t>(frequencyPoints);
    const auto na = static_cast<py::ssize_t>(amplitudePoints);
    py::array_t<unsigned char> overturns({nf, na});
    py::array_t<double> theta({nf, na});
    for (std::size_t k = 0; k < map.overturns.size(); ++k) {
        overturns.mutable_data()[k] = map.overturns[k];
        theta.mutable_data()[k] = map.maxThetaOverAlpha[k];
    }
    py::dict d;
    d["amplitudes"] = toArray(map.amplitudes);
    d["frequencies"] = toArray(map.frequencies);
    d["overturns"] = overturns;
    d["max_theta_over_alpha"] = theta;
    d["alpha_rad"] = blockAlpha(m.block);
    d["p_rad_s"] = blockFrequency(m.block);
    return d;
}

} // namespace

void bindRocking(py::module_& m) {
    m.def("_rocking", &rocking, py::arg("half_width"), py::arg("half_height"),
          py::arg("restitution"), py::arg("linear"), py::arg("mu"), py::arg("initial_tilt"),
          py::arg("duration"), py::arg("pulse"), py::arg("record").none(true), py::arg("amplitude"),
          py::arg("pulse_frequency"), py::arg("pulse_duration"), py::arg("history"),
          py::arg("history_step"));
    m.def("_rocking_critical", &rockingCritical, py::arg("half_width"), py::arg("half_height"),
          py::arg("restitution"), py::arg("linear"), py::arg("mu"), py::arg("pulse"),
          py::arg("record").none(true), py::arg("pulse_frequency"), py::arg("pulse_duration"),
          py::arg("max_amplitude"), py::arg("scan_points"), py::arg("tolerance"));
    m.def("_overturning_map", &overturningMapDict, py::arg("half_width"), py::arg("half_height"),
          py::arg("restitution"), py::arg("linear"), py::arg("mu"), py::arg("shape"),
          py::arg("amplitudes"), py::arg("frequencies"), py::arg("amplitude_points"),
          py::arg("frequency_points"), py::arg("threads"));
}

} // namespace kinstab::python
