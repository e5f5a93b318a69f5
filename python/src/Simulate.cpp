// simulate and simulate_planar: one run under the enveloped sine, with its events and sampled
// history as NumPy arrays when asked.

#include "core/excitation/EnvelopedSine.h"
#include "core/slab/History.h"
#include "core/slab/PlanarCase.h"
#include "core/slab/Slab1DCase.h"
#include "python/src/Arguments.h"
#include "python/src/Arrays.h"
#include "python/src/Bindings.h"
#include "python/src/RunResults.h"

#include <pybind11/stl.h>

#include <cmath>

namespace py = pybind11;

namespace kinstab::python {

namespace {

void checkAmplitudeFrequency(double amplitude, double frequency) {
    finite("amplitude", amplitude);
    finite("frequency", frequency);
    if (!(amplitude >= 0.0 && amplitude <= 1000.0))
        badArgument("amplitude", amplitude, "must be between 0 and 1000 g");
    if (!(frequency > 0.0 && frequency <= 1000.0))
        badArgument("frequency", frequency, "must be > 0 and at most 1000 Hz");
}

SlabRun simulate(const Slab1DCase& c, double amplitude, double frequency, bool events,
                 bool history, double historyStep) {
    checkAmplitudeFrequency(amplitude, frequency);
    finite("history_step", historyStep);
    if (!(historyStep > 0.0)) badArgument("history_step", historyStep, "must be > 0");
    SlabRun run;
    run.tauRef = c.tauRef();
    run.amplitude = amplitude;
    run.frequency = frequency;
    run.keepEvents = events;
    RunOptions options;
    options.recordEvents = events || history;
    {
        py::gil_scoped_release unlocked;
        run.result = runSlab1D(c, amplitude, frequency, options);
        if (history) {
            const EnvelopedSine a(c.envelope, amplitude, frequency, c.tstar);
            run.history =
                sampleHistory(a, c.slab.mu, run.result.events, run.result.tauEnd, historyStep);
        }
    }
    if (!events) run.result.events.clear();
    return run;
}

PlanarRun simulatePlanar(const PlanarCase& c, double amplitude, double frequency, bool events,
                         bool path) {
    checkAmplitudeFrequency(amplitude, frequency);
    PlanarRun run;
    run.tauRef = c.tauRef();
    run.amplitude = amplitude;
    run.frequency = frequency;
    PlanarOptions options = c.solver;
    options.recordEvents = events;
    options.recordPath = path;
    py::gil_scoped_release unlocked;
    const SlabModel2D model = planarModel(c, amplitude, frequency);
    run.result = solvePlanar(model, options);
    return run;
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
          py::arg("frequency"), py::kw_only(), py::arg("events") = false,
          py::arg("path") = false,
          "One run of the planar slab (A_x = amplitude g at frequency Hz across the walls).");
}

} // namespace kinstab::python
