// SPDX-License-Identifier: GPL-3.0-or-later
// simulate and simulate_planar: one run under the enveloped sine, with its events and sampled
// history as NumPy arrays when asked.

#include "core/base/InputLimits.h"
#include "core/base/TextInput.h"
#include "core/excitation/EnvelopedSine.h"
#include "core/excitation/FrequencyRange.h"
#include "core/slab/History.h"
#include "core/slab/PlanarCase.h"
#include "core/slab/Slab1DCase.h"
#include "core/slab/SlabRecorder.h"
#include "python/src/Arguments.h"
#include "python/src/Arrays.h"
#include "python/src/Bindings.h"
#include "python/src/RunResults.h"

#include <pybind11/stl.h>

#include <chrono>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace py = pybind11;

namespace kinstab::python {

namespace {

void checkAmplitudeFrequency(double amplitude, double frequency) {
    keyword(kAmplitudeInput, amplitude);
    keyword(kFrequencyInput, frequency);
}

SlabRun simulate(const Slab1DCase& c, Real amplitude, Real frequency, bool events, bool history,
                 Real historyStep) {
    checkAmplitudeFrequency(amplitude, frequency);
    finite("history_step", historyStep);
    if (!(historyStep > 0.0)) badArgument("history_step", historyStep, "must be > 0");
    SlabRun run;
    run.tauRef = c.tauRef();
    run.amplitude = amplitude;
    run.frequency = frequency;
    {
        py::gil_scoped_release unlocked;
        // The events, and the history sampled from them when asked for.
        const EnvelopedSine a(c.envelope, amplitude, frequency, c.tstar);
        SlabHistoryLog log(a, c.slab.mu);
        run.result = runSlab1D(c, amplitude, frequency, {}, events || history ? &log : nullptr);
        if (history) run.history = log.history(run.result.tauEnd, historyStep);
        if (events) run.events = std::move(log.events);
    }
    return run;
}

PlanarRun simulatePlanar(const PlanarCase& c, Real amplitude, Real frequency, bool events,
                         bool path) {
    checkAmplitudeFrequency(amplitude, frequency);
    PlanarRun run;
    run.tauRef = c.tauRef();
    run.amplitude = amplitude;
    run.frequency = frequency;
    PlanarRecorderPair recorder(events ? &run.events : nullptr, path ? &run.path : nullptr);
    py::gil_scoped_release unlocked;
    const SlabModel2D model = planarModel(c, amplitude, frequency);
    run.result = solvePlanar(model, c.solver, &recorder);
    return run;
}

// The core's own time for runSlab1D, call by call in a C++ loop (for
// examples/python/bench_overhead.py: the overhead of a Python call is the difference).
std::vector<double> coreSeconds(const Slab1DCase& c, Real amplitude, Real frequency, int repeats) {
    checkAmplitudeFrequency(amplitude, frequency);
    if (repeats < 1 || repeats > 1000000)
        badArgument("repeats=" + std::to_string(repeats) + ": must be 1 to 1000000");
    std::vector<double> seconds(static_cast<std::size_t>(repeats));
    py::gil_scoped_release unlocked;
    for (double& s : seconds) {
        const auto t0 = std::chrono::steady_clock::now();
        const SlabResult r = runSlab1D(c, amplitude, frequency);
        const auto t1 = std::chrono::steady_clock::now();
        if (r.outcome == Outcome::Failed) throw std::runtime_error("benchmark run failed");
        s = std::chrono::duration<double>(t1 - t0).count();
    }
    return seconds;
}

} // namespace

void bindSimulate(py::module_& m) {
    bindRunResults(m);
    m.def("simulate", &simulate, py::arg("case"), py::arg("amplitude"), py::arg("frequency"),
          py::kw_only(), py::arg("events") = false, py::arg("history") = false,
          py::arg("history_step") = 0.05,
          "One run of the 1-DOF slab under A e(t) sin(2 pi f t) (amplitude in g, frequency in "
          "Hz). The GIL is released while it runs.");
    m.def("simulate_planar", &simulatePlanar, py::arg("case"), py::arg("amplitude"),
          py::arg("frequency"), py::kw_only(), py::arg("events") = false, py::arg("path") = false,
          "One run of the planar slab (A_x = amplitude g at frequency Hz across the walls).");
    m.def("_core_seconds", &coreSeconds, py::arg("case"), py::arg("amplitude"),
          py::arg("frequency"), py::arg("repeats"));
}

} // namespace kinstab::python
