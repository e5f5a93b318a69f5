// SPDX-License-Identifier: GPL-3.0-or-later
// critical: A_crit(f), the smallest amplitude that collapses the slab, per frequency. Each
// frequency's search runs with the GIL released; Ctrl+C is honoured between frequencies.

#include "core/sweep/Grid.h"
#include "python/src/Arguments.h"
#include "python/src/Bindings.h"
#include "python/src/Models.h"
#include "python/src/SearchArguments.h"

#include <pybind11/numpy.h>

#include <cmath>

namespace py = pybind11;

namespace kinstab::python {

namespace {

py::array_t<double> critical(const py::object& model, const py::object& frequencies,
                             double maxAmplitude, double scanStep, double tolerance) {
    const std::vector<double> freqs = axisValues("frequencies", frequencies);
    if (const std::string e = validateGrid(SweepGrid{{1.0}, freqs}); !e.empty()) badArgument(e);
    const CriticalSearch search = searchFrom(maxAmplitude, scanStep, tolerance);
    const ModelPoint m = modelPointOf(model);
    py::array_t<double> out(static_cast<py::ssize_t>(freqs.size()));
    double* a = out.mutable_data();
    for (std::size_t i = 0; i < freqs.size(); ++i) {
        CriticalResult r;
        {
            py::gil_scoped_release unlocked;
            r = criticalAmplitude(m.point, freqs[i], m.scanFrom, search);
        }
        a[i] = r.amplitude.value_or(std::nan(""));
        if (PyErr_CheckSignals() != 0) throw py::error_already_set();
    }
    return out;
}

} // namespace

void bindCritical(py::module_& m) {
    m.def("_critical", &critical, py::arg("case"), py::arg("frequencies"),
          py::arg("max_amplitude") = kMaxAmplitudeInput.fallback,
          py::arg("scan_step") = kScanStepInput.fallback,
          py::arg("tolerance") = kToleranceInput.fallback);
}

} // namespace kinstab::python
