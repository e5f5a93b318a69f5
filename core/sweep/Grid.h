// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Grids of amplitude and frequency, and the LIST syntax of the command line (docs/user-guide.md
// "The command line"): comma-separated numbers or start:stop:step (stop included when on the grid
// within 1e-9).

#include <string>
#include <vector>

namespace kinstab {

struct ParsedList {
    std::vector<double> values;
    std::string error; // empty when fine
};

ParsedList parseList(const std::string& text);
std::vector<double> linspaceStep(double start, double stop, double step);

struct SweepGrid {
    std::vector<double> amplitudes;  // g
    std::vector<double> frequencies; // Hz
    std::size_t size() const { return amplitudes.size() * frequencies.size(); }
};

std::string validateGrid(const SweepGrid& g); // empty when fine

} // namespace kinstab
