// SPDX-License-Identifier: GPL-3.0-or-later
// critical: A_crit(f), the smallest amplitude that collapses the slab, per frequency: core's
// runAnalysis with the GIL released, the frequencies on its thread pool; Ctrl+C is honoured
// within one search step (runInterruptibly, python/src/Models.h).

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
    AnalysisRequest q = requestFor(model);
    q.criticalFrequencies = axisValues("frequencies", frequencies);
    if (const std::string e = validateGrid(SweepGrid{{1.0}, q.criticalFrequencies}); !e.empty())
        badArgument(e);
    q.criticalSearch = searchFrom(maxAmplitude, scanStep, tolerance);
    q.parts.criticalCurve = true;
    const AnalysisResult r = runInterruptibly(q);
    py::array_t<double> out(static_cast<py::ssize_t>(r.critical->amplitude.size()));
    double* a = out.mutable_data();
    for (std::size_t i = 0; i < r.critical->amplitude.size(); ++i)
        a[i] = r.critical->amplitude[i].value_or(std::nan(""));
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
