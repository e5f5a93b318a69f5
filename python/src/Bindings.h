// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One function per part of the Python module; Module.cpp calls them in order.

#include <pybind11/pybind11.h>

namespace kinstab::python {

void bindCases(pybind11::module_& m);       // Envelope, SlabCase, PlanarCase
void bindSimulate(pybind11::module_& m);    // simulate, simulate_planar and their results
void bindSurface(pybind11::module_& m);     // surface: the (A, f) sweep on threads
void bindCritical(pybind11::module_& m);    // critical: A_crit(f)
void bindRecords(pybind11::module_& m);     // read_record, floor_filter, simulate_record
void bindCodes(pybind11::module_& m);       // codes: the building-code force ratios
void bindFriction(pybind11::module_& m);    // calibrate: the friction law of ch. III
void bindStudy(pybind11::module_& m);       // study_case_count, study_rows (the Dask driver)
void bindAssess(pybind11::module_& m);      // assess: a project's assessment
void bindRisk(pybind11::module_& m);        // _risk_json, _read_hazard: collapse risk
void bindProjectRuns(pybind11::module_& m); // _floors_json, _study_json: kinstab.Project

} // namespace kinstab::python
