// SPDX-License-Identifier: GPL-3.0-or-later
#include "python/src/Models.h"

#include "core/analysis/RunAnalysis.h"
#include "core/sweep/Grid.h"
#include "python/src/Arguments.h"

#include <pybind11/stl.h>

#include <chrono>
#include <future>

namespace py = pybind11;

namespace kinstab::python {

bool isPlanar(const py::handle& model) {
    return py::isinstance<PlanarCase>(model);
}

AnalysisRequest requestFor(const py::handle& model) {
    AnalysisRequest q;
    if (py::isinstance<Slab1DCase>(model))
        q.slab = model.cast<Slab1DCase>();
    else if (isPlanar(model))
        q.planar = model.cast<PlanarCase>();
    else
        badArgument("case: expected a SlabCase or a PlanarCase, got " +
                    py::repr(model).cast<std::string>());
    return q;
}

AnalysisResult runInterruptibly(const AnalysisRequest& request) {
    AnalysisControl control;
    bool interrupted = false;
    AnalysisResult out;
    {
        py::gil_scoped_release unlocked;
        auto work = std::async(std::launch::async, [&] { return runAnalysis(request, control); });
        while (work.wait_for(std::chrono::milliseconds(50)) != std::future_status::ready) {
            py::gil_scoped_acquire locked;
            if (!interrupted && PyErr_CheckSignals() != 0) {
                interrupted = true;
                control.cancel();
            }
        }
        out = work.get(); // rethrows a worker's exception
    }
    if (interrupted) throw py::error_already_set();
    return out;
}

std::vector<double> axisValues(const std::string& keyword, const py::handle& values) {
    if (py::isinstance<py::str>(values)) {
        const ParsedList p = parseList(values.cast<std::string>());
        if (!p.error.empty()) badArgument(keyword + ": " + p.error);
        return p.values;
    }
    try {
        return values.cast<std::vector<double>>();
    } catch (const py::cast_error&) {
        badArgument(keyword + ": expected a sequence of numbers or LIST text, got " +
                    py::repr(values).cast<std::string>());
    }
}

} // namespace kinstab::python
