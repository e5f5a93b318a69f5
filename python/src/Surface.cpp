// SPDX-License-Identifier: GPL-3.0-or-later
// surface: the (A, f) sweep of core's runAnalysis on all cores with the GIL released;
// KeyboardInterrupt arrives within one grid point (runInterruptibly, python/src/Models.h).

#include "core/sweep/Grid.h"
#include "python/src/Arguments.h"
#include "python/src/Bindings.h"
#include "python/src/Models.h"

#include <pybind11/numpy.h>

#include <cmath>

namespace py = pybind11;

namespace kinstab::python {

namespace {

py::dict surfaceArrays(const SweepResult& r, double tauRef, bool planar) {
    const auto na = static_cast<py::ssize_t>(r.grid.amplitudes.size());
    const auto nf = static_cast<py::ssize_t>(r.grid.frequencies.size());
    py::array_t<double> tau({na, nf}), gamma({na, nf});
    py::array_t<std::int8_t> outcome({na, nf}), side({na, nf});
    double* t = tau.mutable_data();
    double* g = gamma.mutable_data();
    std::int8_t* o = outcome.mutable_data();
    std::int8_t* s = side.mutable_data();
    for (std::size_t k = 0; k < r.points.size(); ++k) {
        const PointResult& p = r.points[k];
        const bool collapsed = r.done[k] && p.outcome == Outcome::Collapsed;
        t[k] = collapsed ? p.tauC : std::nan("");
        g[k] = collapsed ? tauRef / p.tauC : 0.0;
        o[k] = r.done[k] ? static_cast<std::int8_t>(p.outcome) : std::int8_t{-1};
        s[k] = static_cast<std::int8_t>(collapsed ? p.exitSide : ExitSide::None);
    }
    py::dict d;
    d["amplitudes"] = py::array_t<double>(na, r.grid.amplitudes.data());
    d["frequencies"] = py::array_t<double>(nf, r.grid.frequencies.data());
    d["tau_c"] = tau;
    d["gamma_c"] = gamma;
    d["outcome"] = outcome;
    d["exit_side"] = planar ? py::object(side) : py::none();
    d["tau_ref"] = tauRef;
    d["wall_time_s"] = r.wallTimeSeconds;
    return d;
}

py::dict surface(const py::object& model, const py::object& amplitudes,
                 const py::object& frequencies, int threads) {
    AnalysisRequest q = requestFor(model);
    q.grid =
        SweepGrid{axisValues("amplitudes", amplitudes), axisValues("frequencies", frequencies)};
    if (const std::string e = validateGrid(q.grid); !e.empty()) badArgument(e);
    if (threads < 0 || threads > 1024)
        badArgument("threads=" + std::to_string(threads) + ": must be 0 (all) to 1024");
    q.threads = threads;
    q.parts.surface = true;
    const AnalysisResult r = runInterruptibly(q);
    return surfaceArrays(*r.surface, r.tauRef, isPlanar(model));
}

} // namespace

void bindSurface(py::module_& m) {
    m.def("_surface", &surface, py::arg("case"), py::arg("amplitudes"), py::arg("frequencies"),
          py::arg("threads") = 0);
    // Names of the codes in the outcome and exit_side arrays (-1 in outcome: not run).
    m.attr("OUTCOMES") =
        py::make_tuple(outcomeName(Outcome::Collapsed), outcomeName(Outcome::Stable),
                       outcomeName(Outcome::LiftOff), outcomeName(Outcome::Failed));
    m.attr("EXIT_SIDES") =
        py::make_tuple(exitSideName(ExitSide::None), exitSideName(ExitSide::Across),
                       exitSideName(ExitSide::Along));
}

} // namespace kinstab::python
