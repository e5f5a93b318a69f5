// SPDX-License-Identifier: GPL-3.0-or-later
// kinstab._core: the Qt-free engine of kinstab as a Python extension (the public face is the
// kinstab package, python/kinstab/__init__.py).

#include "python/src/Bindings.h"

PYBIND11_MODULE(_core, m) {
    m.doc() = "kinstab engine: friction-held slabs in earthquakes (Furgerson 1980)";
    m.attr("__version__") = KINSTAB_VERSION;
    kinstab::python::bindCases(m);
    kinstab::python::bindSimulate(m);
    kinstab::python::bindSurface(m);
    kinstab::python::bindCritical(m);
    kinstab::python::bindRecords(m);
    kinstab::python::bindCodes(m);
    kinstab::python::bindFriction(m);
    kinstab::python::bindStudy(m);
    kinstab::python::bindAssess(m);
    kinstab::python::bindRisk(m);
    kinstab::python::bindProjectRuns(m);
}
