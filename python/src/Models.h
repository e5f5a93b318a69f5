// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What surface() and critical() accept: a SlabCase or a PlanarCase, and a grid axis given as
// numbers or as the command line's LIST text ("0.7:1.15:0.05" or "1,2,3").

#include "core/sweep/ModelPoint.h"

#include <pybind11/pybind11.h>

#include <string>
#include <vector>

namespace kinstab::python {

// Throws ValueError when `model` is neither.
ModelPoint modelPointOf(const pybind11::handle& model);
bool isPlanar(const pybind11::handle& model);
// Throws ValueError "keyword: <parse error>" for bad LIST text.
std::vector<double> axisValues(const std::string& keyword, const pybind11::handle& values);

} // namespace kinstab::python
