// SPDX-License-Identifier: GPL-3.0-or-later
// study_case_count and study_rows: the cases of a study file by index, for the Dask driver
// (python/kinstab/study.py). A row is the JSON line kinstab-cli study writes, to the byte.

#include "core/io/StudyRowJson.h"
#include "core/io/StudySpecJson.h"
#include "core/study/StudyRecords.h"
#include "core/study/StudyRunner.h"
#include "python/src/Bindings.h"
#include "python/src/Interruptible.h"

#include <pybind11/stl.h>

namespace py = pybind11;

namespace kinstab::python {

namespace {

StudySpec loadOrRaise(const std::string& path) {
    try {
        return loadStudy(path);
    } catch (const StudyError& e) {
        throw py::value_error(path + ": " + e.what());
    }
}

std::size_t caseCount(const std::string& path) {
    return studyCaseCount(loadOrRaise(path));
}

std::vector<std::string> rows(const std::string& path, const std::vector<std::size_t>& cases) {
    StudySpec s = loadOrRaise(path);
    const std::size_t n = studyCaseCount(s);
    for (std::size_t i : cases)
        if (i >= n)
            throw py::value_error("cases: " + std::to_string(i) + " is not below the " +
                                  std::to_string(n) + " cases of the study");
    std::vector<std::string> out;
    out.reserve(cases.size());
    // A Dask worker's task: Ctrl+C (KeyboardInterrupt) stops it between two cases, not at the
    // end of the batch.
    SweepControl control;
    bool finished = false;
    try {
        finished = runWatchingSignals(control, [&] {
            loadStudyRecords(s); // each record read once, for every case of the batch
            for (std::size_t i : cases) {
                if (control.isCancelled()) return;
                out.push_back(studyRowLine(runStudyCase(s, studyCase(s, i))));
            }
        });
    } catch (const StudyError& e) {
        throw py::value_error(path + ": " + e.what());
    }
    if (!finished) throw py::error_already_set();
    return out;
}

} // namespace

void bindStudy(py::module_& m) {
    m.def("study_case_count", &caseCount, py::arg("spec"),
          "Number of cases of the study file (records x parameter sets).");
    m.def("study_rows", &rows, py::arg("spec"), py::arg("cases"),
          "The JSON rows of the given cases of the study file, as kinstab-cli study writes them.");
}

} // namespace kinstab::python
