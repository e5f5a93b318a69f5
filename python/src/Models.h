// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What surface() and critical() accept: a SlabCase or a PlanarCase, and a grid axis given as
// numbers or as the command line's LIST text ("0.7:1.15:0.05" or "1,2,3").

#include "core/analysis/AnalysisRequest.h"
#include "core/analysis/AnalysisResult.h"

#include <pybind11/pybind11.h>

#include <string>
#include <vector>

namespace kinstab::python {

// Throws ValueError when `model` is neither.
// A request for the model (a SlabCase or a PlanarCase) with no part asked for yet.
AnalysisRequest requestFor(const pybind11::handle& model);
// core's runAnalysis (its one thread pool) on a helper thread with the GIL released. The calling
// thread stays in charge: it polls for Ctrl+C while the workers run and cancels through the
// analysis control, so KeyboardInterrupt arrives within one point or search step (then
// error_already_set is thrown). A worker's exception is rethrown.
AnalysisResult runInterruptibly(const AnalysisRequest& request);
bool isPlanar(const pybind11::handle& model);
// Throws ValueError "keyword: <parse error>" for bad LIST text.
std::vector<double> axisValues(const std::string& keyword, const pybind11::handle& values);

} // namespace kinstab::python
