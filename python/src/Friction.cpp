// SPDX-License-Identifier: GPL-3.0-or-later
// friction.calibrate: the friction-law calibration of Furgerson 1980 ch. III on a CSV of triplet
// shear tests, checked as `kinstab-cli friction` checks its flags (app/cli/FrictionCommand.cpp).

#include "core/friction/FrictionCalibration.h"
#include "core/friction/TripletCsv.h"
#include "core/io/FrictionJson.h"
#include "python/src/Arguments.h"
#include "python/src/Bindings.h"

#include <pybind11/stl.h>

#include <cmath>

namespace py = pybind11;

namespace kinstab::python {

namespace {

CalibrationOptions calibrationOptions(std::optional<double> bearingArea, double alpha,
                                      const std::string& beta, double maxCp, double outlierAlpha,
                                      int outlierMinRuns, bool keepOutliers) {
    CalibrationOptions o;
    if (bearingArea) {
        if (!(*bearingArea > 0.0) || !std::isfinite(*bearingArea))
            badArgument("bearing_area", *bearingArea, "must be > 0 (in^2)");
        o.bearingAreaIn2 = *bearingArea;
    }
    o.fit.alpha = alpha;
    if (alpha != 0.0 && alpha != 2.0)
        badArgument("alpha", alpha, "must be 0 or 2 (Furgerson 1980 Eq. 3)");
    if (choice("beta", beta, "0|1/3|best") == "0") o.betas = {0.0};
    if (beta == "1/3") o.betas = {1.0 / 3.0};
    o.maxCpPsi = finite("max_cp", maxCp);
    if (!(maxCp > 0.0)) badArgument("max_cp", maxCp, "must be > 0 (psi)");
    o.outlierAlpha = finite("outlier_alpha", outlierAlpha);
    if (!(outlierAlpha > 0.0 && outlierAlpha < 0.5))
        badArgument("outlier_alpha", outlierAlpha, "must be in (0, 0.5)");
    o.outlierMinRuns = outlierMinRuns;
    if (outlierMinRuns < 3)
        badArgument("outlier_min_runs=" + std::to_string(outlierMinRuns) + ": must be at least 3");
    o.excludeOutliers = !keepOutliers;
    return o;
}

std::string calibrateJson(const std::string& path, std::optional<double> bearingArea, double alpha,
                          const std::string& beta, double maxCp, double outlierAlpha,
                          int outlierMinRuns, bool keepOutliers) {
    const CalibrationOptions o = calibrationOptions(bearingArea, alpha, beta, maxCp, outlierAlpha,
                                                    outlierMinRuns, keepOutliers);
    try {
        const std::vector<TripletCurve> runs = readTripletCsv(path);
        nlohmann::json j = frictionCalibrationJson(calibrateFriction(runs, o));
        j["data"] = path;
        return j.dump();
    } catch (const TripletCsvError& e) {
        badArgument(std::string("data ") + e.what());
    } catch (const std::invalid_argument& e) {
        badArgument("data " + path + ": " + e.what());
    }
}

} // namespace

void bindFriction(py::module_& m) {
    m.def("_calibrate_json", &calibrateJson, py::arg("data"), py::arg("bearing_area") = py::none(),
          py::arg("alpha") = 2.0, py::arg("beta") = "best", py::arg("max_cp") = 400.0,
          py::arg("outlier_alpha") = 0.05, py::arg("outlier_min_runs") = 5,
          py::arg("keep_outliers") = false);
}

} // namespace kinstab::python
