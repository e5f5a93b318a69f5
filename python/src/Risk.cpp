// SPDX-License-Identifier: GPL-3.0-or-later
// risk and read_hazard: core/risk's request answered (core/risk/RiskReport.h), the same JSON as
// kinstab-cli risk; a hazard curve read by core's readers. A bad argument raises ValueError named
// by its keyword, a bad file one naming the file and line, as the CLI's exit 2.

#include "core/base/TextInput.h"
#include "core/io/StudyRowJson.h"
#include "core/risk/RiskReport.h"
#include "python/src/Arguments.h"
#include "python/src/Arrays.h"
#include "python/src/Bindings.h"

#include <pybind11/stl.h>

#include <utility>

namespace py = pybind11;

namespace kinstab::python {

namespace {

using Site = std::optional<std::pair<double, double>>;

[[noreturn]] void badRequest(const RiskProblem& p) {
    const std::string why = renderRiskKeys(p.why, [](const std::string& key) { return key; });
    if (p.value) badArgument(p.key, *p.value, why);
    badArgument(p.key + ": " + why);
}

HazardFormat formatFrom(const std::string& name) {
    return *hazardFormatFromName(choice("hazard_format", name, "auto|csv|openquake|usgs"));
}

std::optional<HazardSite> siteFrom(const Site& s) {
    if (!s) return std::nullopt;
    return HazardSite{finite("site[0]", s->first), finite("site[1]", s->second)};
}

std::string riskJson(const std::string& hazard, const std::string& format, const Site& site,
                     const std::optional<std::string>& results, std::optional<long long> set,
                     std::optional<double> median, std::optional<double> beta,
                     const std::optional<std::string>& measure, double years,
                     std::optional<double> targetRate, std::optional<double> im,
                     long long resamples, unsigned long long seed) {
    RiskRequest r;
    r.hazard = hazard;
    r.format = formatFrom(format);
    r.site = siteFrom(site);
    r.results = results;
    if (set && *set < 0) badArgument("set", double(*set), "must be a set number >= 0");
    if (set) r.set = static_cast<std::size_t>(*set);
    r.median = median;
    r.beta = beta;
    r.measure = measure;
    r.settings.years = years;
    if (targetRate) r.settings.targetRate = *targetRate;
    r.settings.imG = im;
    if (resamples < 0) badArgument("bootstrap", double(resamples), "must be 0 to 100000");
    r.bootstrap.resamples = static_cast<std::size_t>(resamples);
    r.bootstrap.seed = seed;
    try {
        py::gil_scoped_release unlocked; // the bootstrap's fits need no Python
        return riskReport(r).dump();
    } catch (const RiskRequestError& e) {
        badRequest(e.problem);
    } catch (const HazardError& e) {
        badArgument(std::string("hazard: ") + e.what());
    } catch (const StudyRowError& e) {
        badArgument(std::string("results: ") + e.what());
    }
}

py::dict readHazard(const std::string& path, const std::string& format, const Site& site,
                    const std::optional<std::string>& measure) {
    HazardRequest request{formatFrom(format), siteFrom(site), std::nullopt};
    if (measure) {
        request.measure = measureFromText(*measure);
        if (!request.measure)
            badArgument("measure: " + quotedToken(*measure) +
                        " is no measure a hazard curve is given in");
    }
    try {
        const HazardCurve c = readHazardFile(path, request);
        py::dict d;
        d["source"] = c.source;
        d["format"] = c.format;
        d["intensity_measure"] = hazardMeasureName(c.measure);
        d["im_g"] = column<double>(c.points, [](const HazardPoint& p) { return p.imG; });
        d["annual_rate"] =
            column<double>(c.points, [](const HazardPoint& p) { return p.annualRate; });
        d["zero_rate_points_dropped"] = c.zeroRatePointsDropped;
        return d;
    } catch (const HazardError& e) {
        badArgument(std::string("path: ") + e.what());
    }
}

} // namespace

void bindRisk(py::module_& m) {
    m.def("_risk_json", &riskJson, py::arg("hazard"), py::arg("hazard_format"), py::arg("site"),
          py::arg("results"), py::arg("set"), py::arg("median"), py::arg("beta"),
          py::arg("measure"), py::arg("years"), py::arg("target_rate"), py::arg("im"),
          py::arg("bootstrap"), py::arg("seed"));
    m.def("_read_hazard", &readHazard, py::arg("path"), py::arg("hazard_format") = "auto",
          py::arg("site") = py::none(), py::arg("measure") = py::none());
}

} // namespace kinstab::python
