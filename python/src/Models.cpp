// SPDX-License-Identifier: GPL-3.0-or-later
#include "python/src/Models.h"

#include "core/sweep/Grid.h"
#include "python/src/Arguments.h"

#include <pybind11/stl.h>

namespace py = pybind11;

namespace kinstab::python {

bool isPlanar(const py::handle& model) {
    return py::isinstance<PlanarCase>(model);
}

ModelPoint modelPointOf(const py::handle& model) {
    if (py::isinstance<Slab1DCase>(model))
        return modelPoint(model.cast<Slab1DCase>(), std::nullopt);
    if (isPlanar(model)) return modelPoint(Slab1DCase{}, model.cast<PlanarCase>());
    badArgument("case: expected a SlabCase or a PlanarCase, got " +
                py::repr(model).cast<std::string>());
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
