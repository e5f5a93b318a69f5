// SPDX-License-Identifier: GPL-3.0-or-later
// read_record, floor_filter and simulate_record: accelerograms as NumPy arrays, the floor
// filter (Nigam & Jennings 1969 recurrence) and a run of the 1-DOF slab under a record.

#include "core/base/InputLimits.h"
#include "core/base/TextInput.h"
#include "core/check/RecordAnalysis.h"
#include "core/excitation/FloorFilter.h"
#include "core/excitation/RecordMetrics.h"
#include "core/excitation/RecordedMotion.h"
#include "core/records/RecordReader.h"
#include "core/slab/History.h"
#include "python/src/Arguments.h"
#include "python/src/Arrays.h"
#include "python/src/Bindings.h"
#include "python/src/RunResults.h"
#include "python/src/SearchArguments.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>

namespace py = pybind11;

namespace kinstab::python {

namespace {

RecordReadOptions readOptions(const std::string& format, std::optional<double> dt,
                              std::optional<std::string> unit, const std::string& channel) {
    RecordReadOptions o;
    o.format =
        *recordFormatFromName(choice("format", format, "at2|auto|cosmos|csmip|time-accel|values"));
    if (dt) o.dt = keyword(kRecordDtInput, *dt);
    if (unit) {
        o.unit = accelUnitFromName(*unit);
        if (!o.unit)
            badArgument("unit='" + *unit + "': must be one of g, m/s2, cm/s2, ft/s2, in/s2");
    }
    o.channel = channel;
    if (o.format == RecordFormat::Values && !o.dt)
        badArgument("format='values': needs dt (the file has no time column)");
    return o;
}

Accelerogram readRecordFile(const std::string& path, const std::string& format,
                            std::optional<double> dt, std::optional<std::string> unit,
                            const std::string& channel) {
    const RecordReadOptions o = readOptions(format, dt, unit, channel);
    try {
        py::gil_scoped_release unlocked;
        return readRecord(path, o);
    } catch (const RecordError& e) {
        badArgument("path='" + nulShown(path) + "': " + e.what());
    }
}

FloorFilterParams floorParams(double period, double damping, std::optional<double> tail) {
    FloorFilterParams p{finite("period", period), finite("damping", damping), tail};
    if (const InputProblem e = checkFloorFilter(p); !e.empty())
        badArgument(e.key == "period_s" ? "period"
                    : e.key == "tail_s" ? "tail"
                                        : e.key,
                    e.value, e.why);
    return p;
}

Accelerogram floorFilter(const Accelerogram& ground, Real period, Real damping,
                         std::optional<Real> tail) {
    const FloorFilterParams p = floorParams(period, damping, real(tail));
    py::gil_scoped_release unlocked;
    return floorMotion(ground, p);
}

py::array_t<double> sampleTimes(const Accelerogram& a) {
    py::array_t<double> t(static_cast<py::ssize_t>(a.size()));
    double* out = t.mutable_data();
    for (std::size_t i = 0; i < a.size(); ++i)
        out[i] = static_cast<double>(i) * a.dt;
    return t;
}

py::object orNone(const std::optional<double>& v) {
    return v ? py::object(py::float_(*v)) : py::object(py::none());
}

// The record's catalogue numbers (core/excitation/RecordMetrics.h), SI units named in the keys.
py::dict metricsDict(const Accelerogram& a, std::optional<Real> saPeriod) {
    std::optional<double> period = real(saPeriod);
    if (period) {
        const FloorFilterParams p{finite("sa_period", *period), kSpectralDamping, 0.0};
        if (const InputProblem e = checkFloorFilter(p); !e.empty())
            badArgument("sa_period", *period, e.why);
    }
    RecordMetrics m;
    {
        py::gil_scoped_release unlocked;
        m = recordMetrics(a, period);
    }
    py::dict d;
    d["pga_g"] = m.pga;
    d["pgv_m_s"] = m.pgv;
    d["pgd_m"] = m.pgd;
    d["final_velocity_m_s"] = m.finalVelocity;
    d["arias_m_s"] = m.arias;
    d["t5_s"] = orNone(m.t5);
    d["t95_s"] = orNone(m.t95);
    d["d5_95_s"] = orNone(m.d5_95);
    d["mean_period_s"] = orNone(m.meanPeriod);
    d["sa_period_s"] = orNone(period);
    d["sa_damping"] = kSpectralDamping;
    d["sa_g"] = m.sa ? py::object(py::float_(m.sa->g)) : py::object(py::none());
    return d;
}

void bindRecord(py::module_& m) {
    py::class_<Accelerogram>(m, "Record", "An accelerogram: equally spaced samples in g.")
        .def_readonly("dt", &Accelerogram::dt, "s")
        .def_property_readonly(
            "samples", [](const Accelerogram& a) { return toArray(a.samples); }, "g")
        .def_property_readonly("time", &sampleTimes, "s, from the first sample")
        .def_readonly("name", &Accelerogram::name)
        .def_readonly("station", &Accelerogram::station)
        .def_readonly("component", &Accelerogram::component)
        .def_readonly("source_file", &Accelerogram::sourceFile)
        .def_readonly("format", &Accelerogram::format)
        .def_property_readonly("file_unit",
                               [](const Accelerogram& a) { return accelUnitName(a.fileUnit); })
        .def_readonly("header_peak", &Accelerogram::headerPeak, "g, when the header states one")
        .def_property_readonly("duration", &Accelerogram::duration, "s")
        .def_property_readonly(
            "peak", [](const Accelerogram& a) { return a.peak().value; },
            "the signed sample of largest |a|, g")
        .def_property_readonly("peak_time", [](const Accelerogram& a) { return a.peak().time; })
        .def("metrics", &metricsDict, py::arg("sa_period") = py::none(),
             "PGA (g), PGV (m/s), PGD (m), Arias intensity (m/s), D5-95 (s), mean period Tm "
             "(s, Rathje et al. 1998) and, with sa_period (s), Sa(T, 5 %) in g: a dict. "
             "Integrated exactly for the linear-between-samples record from rest, without "
             "baseline correction (final_velocity_m_s shows the drift).")
        .def("__len__", &Accelerogram::size)
        .def("__repr__", [](const Accelerogram& a) {
            return "<Record " + a.name + " " + a.component + ": " + std::to_string(a.size()) +
                   " samples, dt=" + shown(a.dt) + " s>";
        });
    m.def("read_record", &readRecordFile, py::arg("path"), py::kw_only(),
          py::arg("format") = "auto", py::arg("dt") = py::none(), py::arg("unit") = py::none(),
          py::arg("channel") = "",
          "Reads a PEER AT2, COSMOS, CSMIP V2, values or time-accel file.");
    m.def("floor_filter", &floorFilter, py::arg("record"), py::arg("period"),
          py::arg("damping") = 0.02, py::arg("tail") = py::none(),
          "The floor's absolute acceleration: a damped SDOF (period s, damping ratio) on the "
          "record, with a free-vibration tail (default: until it decays to 1 %, at most 120 s).");
}

// What simulate_record runs, from its keywords but the search's; a bad one raises ValueError
// naming it.
RecordAnalysisInput recordInput(const Slab1DCase& c, const std::string& path,
                                std::optional<double> amplitude, std::optional<double> scaleFactor,
                                std::optional<double> floorPeriod, double damping, bool critical) {
    RecordAnalysisInput in;
    in.slab = c;
    if (c.solver != SolverKind::Exact)
        badArgument("solver='" + solverName(c.solver) +
                    "': only the exact solver runs recorded motions");
    in.record.file = path;
    if (floorPeriod) in.record.floor = floorParams(*floorPeriod, damping, std::nullopt);
    if (amplitude && scaleFactor)
        badArgument("scale_factor", *scaleFactor, "amplitude and scale_factor exclude each other");
    if (amplitude) in.record.targetPeak = keyword(kTargetPeakInput, *amplitude);
    in.record.scaleFactor = keyword(kScaleFactorInput, scaleFactor.value_or(1.0));
    in.critical = critical;
    return in;
}

// simulate_record's result: the run, the motion's scaling, the critical peak, and the events
// and history when asked for.
py::dict recordRunDict(const RecordAnalysis& a, const SlabEventLog& log, bool events,
                       const std::optional<History>& history) {
    py::dict d;
    d["outcome"] = outcomeName(a.run.outcome);
    d["tau_c"] = collapseTau(a.run);
    d["gamma_c"] = a.tauRef ? gammaC(a.run, *a.tauRef) : std::nan("");
    d["tau_ref"] = a.tauRef.value_or(std::nan(""));
    d["tau_end"] = a.run.tauEnd;
    d["max_abs_delta"] = a.run.maxAbsDelta;
    d["residual_delta"] = a.run.residualDelta;
    d["slip_intervals"] = a.run.slipIntervals;
    d["amplitude"] = a.peak;
    d["scale_factor"] = a.scaleFactor;
    d["ground"] = a.ground;
    d["motion"] = a.motion;
    d["critical_peak"] = a.critical && a.critical->peak ? *a.critical->peak : std::nan("");
    d["work"] = workDict(a.run.work);
    d["events"] = events ? py::object(slabEventArrays(log.events)) : py::none();
    d["history"] = history ? py::object(historyArrays(*history)) : py::none();
    return d;
}

py::dict recordRun(const Slab1DCase& c, const std::string& path, std::optional<double> amplitude,
                   std::optional<double> scaleFactor, std::optional<double> floorPeriod,
                   double damping, bool critical, double maxAmplitude, double scanStep,
                   double tolerance, bool events, std::optional<double> historyStep) {
    RecordAnalysisInput in =
        recordInput(c, path, amplitude, scaleFactor, floorPeriod, damping, critical);
    in.search = searchFrom(maxAmplitude, scanStep, tolerance);
    if (historyStep) {
        finite("history_step", *historyStep);
        if (!(*historyStep > 0.0)) badArgument("history_step", *historyStep, "must be > 0");
    }
    SlabEventLog log; // the single run's events, and the history sampled from them
    RecordAnalysis a;
    std::optional<History> history;
    try {
        py::gil_scoped_release unlocked;
        a = analyseRecord(in, nullptr, events || historyStep ? &log : nullptr);
        if (historyStep) {
            const RecordedMotion motion(a.motion, c.tstar, a.peak);
            history = sampleHistory(motion, c.slab.mu, log.events, a.run.tauEnd, *historyStep);
        }
    } catch (const RecordError& e) {
        badArgument("path='" + nulShown(path) + "': " + e.what());
    } catch (const std::invalid_argument& e) {
        badArgument("path='" + nulShown(path) + "': " + e.what());
    }
    return recordRunDict(a, log, events, history);
}

} // namespace

void bindRecords(py::module_& m) {
    bindRecord(m);
    // Every number a Real: True or False where a number belongs raises TypeError.
    m.def(
        "_simulate_record",
        [](const Slab1DCase& c, const std::string& path, std::optional<Real> amplitude,
           std::optional<Real> scaleFactor, std::optional<Real> floorPeriod, Real damping,
           bool critical, Real maxAmplitude, Real scanStep, Real tolerance, bool events,
           std::optional<Real> historyStep) {
            return recordRun(c, path, real(amplitude), real(scaleFactor), real(floorPeriod),
                             damping, critical, maxAmplitude, scanStep, tolerance, events,
                             real(historyStep));
        },
        py::arg("case"), py::arg("path"), py::arg("amplitude") = py::none(),
        py::arg("scale_factor") = py::none(), py::arg("floor_period") = py::none(),
        py::arg("damping") = 0.02, py::arg("critical") = false,
        py::arg("max_amplitude") = kMaxAmplitudeInput.fallback,
        py::arg("scan_step") = kScanStepInput.fallback,
        py::arg("tolerance") = kToleranceInput.fallback, py::arg("events") = false,
        py::arg("history_step") = py::none());
}

} // namespace kinstab::python
