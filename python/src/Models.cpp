// SPDX-License-Identifier: GPL-3.0-or-later
#include "python/src/Models.h"

#include "core/analysis/RunAnalysis.h"
#include "core/sweep/Grid.h"
#include "python/src/Arguments.h"
#include "python/src/Interruptible.h"

#include <pybind11/stl.h>

namespace py = pybind11;

namespace kinstab::python {

bool isPlanar(const py::handle& model) {
    return py::isinstance<PlanarCase>(model);
}

AnalysisRequest requestFor(const py::handle& model) {
    AnalysisRequest q;
    if (py::isinstance<Slab1DCase>(model))
        q.slab = model.cast<Slab1DCase>();
    else if (isPlanar(model)) { // the 1-DOF case it holds and its own inputs
        const PlanarCase c = model.cast<PlanarCase>();
        q.slab = c.common;
        q.planar = c.own();
    } else
        badArgument("case: expected a SlabCase or a PlanarCase, got " +
                    py::repr(model).cast<std::string>());
    return q;
}

AnalysisResult runInterruptibly(const AnalysisRequest& request) {
    AnalysisControl control;
    AnalysisResult out;
    // AnalysisControl::cancel is its sweep control's cancel: the one the poll sets.
    if (!runWatchingSignals(control.sweepControl(), [&] { out = runAnalysis(request, control); }))
        throw py::error_already_set();
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
