// SPDX-License-Identifier: GPL-3.0-or-later
#include "python/src/RunResults.h"

#include "python/src/Arrays.h"

#include <pybind11/stl.h>

#include <cmath>

namespace py = pybind11;

namespace kinstab::python {

double collapseTau(const SlabResult& r) {
    return r.outcome == Outcome::Collapsed ? r.tauC : std::nan("");
}

double gammaC(const SlabResult& r, double tauRef) {
    return r.outcome == Outcome::Collapsed ? tauRef / r.tauC : 0.0;
}

py::dict workDict(const SolverWork& w) {
    py::dict d;
    d["accel_evaluations"] = w.accelEvaluations;
    d["root_iterations"] = w.rootIterations;
    d["steps"] = w.steps;
    d["events"] = w.events;
    d["restarts"] = w.restarts;
    return d;
}

namespace {

py::list kindNames(const std::vector<SlabEvent>& events) {
    py::list kinds;
    for (const auto& e : events)
        kinds.append(eventKindName(e.kind));
    return kinds;
}

py::dict planarEventArrays(const std::vector<PlanarEvent>& ev) {
    py::dict d;
    d["tau"] = column<double>(ev, [](const PlanarEvent& e) { return e.tau; });
    py::list kinds;
    for (const auto& e : ev)
        kinds.append(eventKindName(e.kind));
    d["kind"] = kinds;
    d["dx"] = column<double>(ev, [](const PlanarEvent& e) { return e.dx; });
    d["dy"] = column<double>(ev, [](const PlanarEvent& e) { return e.dy; });
    d["ux"] = column<double>(ev, [](const PlanarEvent& e) { return e.ux; });
    d["uy"] = column<double>(ev, [](const PlanarEvent& e) { return e.uy; });
    return d;
}

py::dict pathArrays(const std::vector<PlanarSample>& p) {
    py::dict d;
    d["tau"] = column<double>(p, [](const PlanarSample& s) { return s.tau; });
    d["dx"] = column<double>(p, [](const PlanarSample& s) { return s.dx; });
    d["dy"] = column<double>(p, [](const PlanarSample& s) { return s.dy; });
    d["ux"] = column<double>(p, [](const PlanarSample& s) { return s.ux; });
    d["uy"] = column<double>(p, [](const PlanarSample& s) { return s.uy; });
    d["slipping"] = column<bool>(p, [](const PlanarSample& s) { return s.slipping; });
    return d;
}

// The keys both results share, read through `slab` (the run's SlabResult).
template <typename Run, typename Get> void defineCommon(py::class_<Run>& c, Get slab) {
    c.def_property_readonly("outcome",
                            [slab](const Run& r) { return outcomeName(slab(r).outcome); })
        .def_property_readonly(
            "tau_c", [slab](const Run& r) { return collapseTau(slab(r)); },
            "collapse time tau_c = t_c / t* (NaN when not collapsed)")
        .def_property_readonly(
            "gamma_c", [slab](const Run& r) { return gammaC(slab(r), r.tauRef); },
            "tau_ref / tau_c (0 when not collapsed)")
        .def_readonly("tau_ref", &Run::tauRef)
        .def_readonly("amplitude", &Run::amplitude)
        .def_readonly("frequency", &Run::frequency)
        .def_property_readonly("tau_end", [slab](const Run& r) { return slab(r).tauEnd; })
        .def_property_readonly("slip_intervals",
                               [slab](const Run& r) { return slab(r).slipIntervals; })
        .def_property_readonly("max_abs_delta",
                               [slab](const Run& r) { return slab(r).maxAbsDelta; })
        .def_property_readonly("residual_delta",
                               [slab](const Run& r) { return slab(r).residualDelta; })
        .def_property_readonly("failure", [slab](const Run& r) { return slab(r).failure; })
        .def_property_readonly("work", [slab](const Run& r) { return workDict(slab(r).work); });
}

} // namespace

py::dict slabEventArrays(const std::vector<SlabEvent>& events) {
    py::dict d;
    d["tau"] = column<double>(events, [](const SlabEvent& e) { return e.tau; });
    d["kind"] = kindNames(events);
    d["delta"] = column<double>(events, [](const SlabEvent& e) { return e.delta; });
    d["velocity"] = column<double>(events, [](const SlabEvent& e) { return e.velocity; });
    d["direction"] = column<std::int8_t>(events, [](const SlabEvent& e) { return e.direction; });
    return d;
}

py::dict historyArrays(const History& h) {
    const auto& s = h.samples;
    py::dict d;
    d["tau"] = column<double>(s, [](const HistorySample& x) { return x.tau; });
    d["accel"] = column<double>(s, [](const HistorySample& x) { return x.accel; });
    d["delta"] = column<double>(s, [](const HistorySample& x) { return x.delta; });
    d["velocity"] = column<double>(s, [](const HistorySample& x) { return x.velocity; });
    d["state"] = column<std::int8_t>(s, [](const HistorySample& x) { return x.state; });
    return d;
}

void bindRunResults(py::module_& m) {
    py::class_<SlabRun> slab(m, "SimulationResult", "One run of the 1-DOF slab.");
    defineCommon(slab, [](const SlabRun& r) -> const SlabResult& { return r.result; });
    slab.def_property_readonly(
            "events",
            [](const SlabRun& r) -> py::object {
                if (!r.events) return py::none();
                return slabEventArrays(*r.events);
            },
            "dict of arrays tau, kind (list of str), delta, velocity, direction; None unless "
            "asked for with events=True")
        .def_property_readonly(
            "history",
            [](const SlabRun& r) -> py::object {
                if (!r.history) return py::none();
                return historyArrays(*r.history);
            },
            "dict of arrays tau, accel (g), delta, velocity, state (0 stick, +-1 slip); None "
            "unless asked for with history=True")
        .def("__repr__", [](const SlabRun& r) {
            return "<SimulationResult " + outcomeName(r.result.outcome) +
                   " tau_c=" + py::repr(py::float_(collapseTau(r.result))).cast<std::string>() +
                   ">";
        });

    py::class_<PlanarRun> planar(m, "PlanarResult", "One run of the planar slab.");
    defineCommon(planar, [](const PlanarRun& r) -> const SlabResult& { return r.result.slab; });
    planar
        .def_property_readonly("exit_side",
                               [](const PlanarRun& r) { return exitSideName(r.result.exitSide); })
        .def_property_readonly("tau_lift_off",
                               [](const PlanarRun& r) { return r.result.tauLiftOff; })
        .def_property_readonly("max_abs_delta_y",
                               [](const PlanarRun& r) { return r.result.maxAbsDeltaY; })
        .def_property_readonly("residual_delta_y",
                               [](const PlanarRun& r) { return r.result.residualDeltaY; })
        .def_property_readonly(
            "events", [](const PlanarRun& r) { return planarEventArrays(r.events.events); })
        .def_property_readonly("path", [](const PlanarRun& r) { return pathArrays(r.path.path); });
}

} // namespace kinstab::python
