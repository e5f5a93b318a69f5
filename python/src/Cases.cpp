// SPDX-License-Identifier: GPL-3.0-or-later
// Envelope, SlabCase and PlanarCase: the inputs of every run, checked once when made.

#include "python/src/Arguments.h"
#include "python/src/Bindings.h"
#include "python/src/PlanarArguments.h"
#include "python/src/SlabCaseArguments.h"

#include <pybind11/stl.h>

namespace py = pybind11;

namespace kinstab::python {

namespace {

py::dict timesDict(const CharacteristicTimes& t) {
    py::dict d;
    d["tau_rise"] = t.tauRise;
    d["tau_max"] = t.tauMax;
    d["tau_dur"] = t.tauDur;
    return d;
}

Envelope envelopeFrom(const py::object& e) {
    if (py::isinstance<py::str>(e)) return presetEnvelope(e.cast<std::string>());
    if (py::isinstance<Envelope>(e)) return e.cast<Envelope>();
    badArgument("envelope: expected 'fast', 'moderate', 'slow' or an Envelope, got " +
                py::repr(e).cast<std::string>());
}

void bindEnvelope(py::module_& m) {
    py::class_<Envelope>(m, "Envelope",
                         R"(The floor-motion envelope e(t) = exp(-alpha t) - exp(-beta t)
(Furgerson 1980, ch. IV). Envelope(alpha, beta) in 1/s, or a preset: Envelope.preset("fast"),
"moderate" or "slow".)")
        .def(py::init(&customEnvelope), py::arg("alpha"), py::arg("beta"))
        .def_static("preset", &presetEnvelope, py::arg("name"),
                    "One of the paper's presets: 'fast', 'moderate' or 'slow'.")
        .def_readonly("alpha", &Envelope::alpha, "1/s")
        .def_readonly("beta", &Envelope::beta, "1/s")
        .def_property_readonly("name", &Envelope::name)
        .def_property_readonly(
            "preset_name",
            [](const Envelope& e) -> py::object {
                if (!e.preset) return py::none();
                return py::str(presetName(*e.preset));
            },
            "The preset's name, or None for a custom envelope.")
        .def(
            "times",
            [](const Envelope& e, double tstar, bool computed) {
                return timesDict(computed ? e.computedTimes(tstar) : e.scalingTimes(tstar));
            },
            py::arg("tstar") = 0.099, py::arg("computed") = false,
            "tau_rise, tau_max, tau_dur (dimensionless) as gamma_c uses them (a preset: the "
            "paper's Table 4), or computed from alpha and beta.")
        .def("__repr__", [](const Envelope& e) -> std::string {
            return e.preset ? "Envelope.preset('" + presetName(*e.preset) + "')"
                            : "Envelope(alpha=" + shown(e.alpha) + ", beta=" + shown(e.beta) + ")";
        });
}

Slab1DCase makeSlabCase(const py::object& envelope, std::optional<double> tstar,
                        std::optional<double> wallWidthIn, double mu, double limit,
                        std::optional<double> duration, const std::string& scale,
                        const std::string& solver, double paperSteps) {
    SlabCaseArguments a;
    a.envelope = envelopeFrom(envelope);
    a.tstar = tstar;
    a.wallWidthIn = wallWidthIn;
    a.mu = mu;
    a.limit = limit;
    a.duration = duration;
    a.scale = scale;
    a.solver = solver;
    a.paperSteps = paperSteps;
    return slabCaseFrom(a);
}

void bindSlabCase(py::module_& m) {
    py::class_<Slab1DCase>(m, "SlabCase", R"(One 1-DOF slab case: everything but amplitude and
frequency. Checked when made: a bad value raises ValueError naming the keyword.)")
        .def(py::init(&makeSlabCase), py::kw_only(), py::arg("envelope") = "moderate",
             py::arg("tstar") = py::none(), py::arg("wall_width_in") = py::none(),
             py::arg("mu") = kMuInput.fallback, py::arg("limit") = kLimitInput.fallback,
             py::arg("duration") = py::none(), py::arg("scale") = "tau_max",
             py::arg("solver") = "exact", py::arg("paper_steps") = kPaperStepsInput.fallback)
        .def_readonly("envelope", &Slab1DCase::envelope)
        .def_readonly("tstar", &Slab1DCase::tstar, "s")
        .def_property_readonly("mu", [](const Slab1DCase& c) { return c.slab.mu; })
        .def_property_readonly("limit", [](const Slab1DCase& c) { return c.slab.limit; })
        .def_property_readonly("duration", [](const Slab1DCase& c) { return c.slab.duration; })
        .def_property_readonly("scale", [](const Slab1DCase& c) { return tauScaleName(c.scale); })
        .def_property_readonly("solver", [](const Slab1DCase& c) { return solverName(c.solver); })
        .def_readonly("paper_steps", &Slab1DCase::paperStepsPerPeriod)
        .def_property_readonly("tau_ref", &Slab1DCase::tauRef,
                               "gamma_c = tau_ref / tau_c (the scale's characteristic time)");
}

PlanarCase makePlanarCase(const Slab1DCase& common, double fy, double ayRatio, double theta,
                          const std::string& normalization, std::optional<std::string> vertical) {
    return planarCaseFrom(common, PlanarArguments{fy, ayRatio, theta, normalization, vertical});
}

void bindPlanarCase(py::module_& m) {
    py::class_<PlanarCase>(m, "PlanarCase", R"(The planar slab of Furgerson 1980 ch. VI: the
1-DOF case's envelope, t*, mu, limit, duration and scale, plus the motion along the walls
(A_y = ay_ratio A_x at fy Hz), the along-wall limit theta and an optional vertical record.)")
        .def(py::init(&makePlanarCase), py::arg("common"), py::kw_only(), py::arg("fy"),
             py::arg("ay_ratio") = kAyRatioInput.fallback, py::arg("theta") = kThetaInput.fallback,
             py::arg("normalization") = "product", py::arg("vertical") = py::none())
        .def_readonly("fy", &PlanarCase::fyHz, "Hz")
        .def_readonly("ay_ratio", &PlanarCase::ayRatio)
        .def_property_readonly("theta", [](const PlanarCase& c) { return c.theta; })
        .def_property_readonly("mu", [](const PlanarCase& c) { return c.common.slab.mu; })
        .def_property_readonly("limit", [](const PlanarCase& c) { return c.common.slab.limit; })
        .def_property_readonly("tstar", [](const PlanarCase& c) { return c.common.tstar; })
        .def_property_readonly(
            "normalization", [](const PlanarCase& c) { return normalizationName(c.normalization); })
        .def_property_readonly("has_vertical",
                               [](const PlanarCase& c) { return c.vertical != nullptr; })
        .def_property_readonly("tau_ref", &PlanarCase::tauRef);
}

} // namespace

void bindCases(py::module_& m) {
    bindEnvelope(m);
    bindSlabCase(m);
    bindPlanarCase(m);
}

} // namespace kinstab::python
