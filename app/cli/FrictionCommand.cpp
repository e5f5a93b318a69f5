// SPDX-License-Identifier: GPL-3.0-or-later
// kinstab-cli friction: the friction-law calibration of Furgerson (1980) ch. III on triplet
// shear test data (docs/theory.md §8): decay-law fits per configuration and CP, the outlier test,
// the confidence intervals and mu_inf, as JSON.

#include "app/cli/Args.h"
#include "app/cli/Commands.h"
#include "core/friction/FrictionCalibration.h"
#include "core/friction/TripletCsv.h"
#include "core/io/FrictionJson.h"
#include "core/io/JsonText.h"

#include <stdexcept>

namespace kinstab::cli {
namespace {

CalibrationOptions optionsFromFlags(const Args& args) {
    CalibrationOptions o;
    if (const auto a = args.optionalNumber("bearing-area")) {
        if (!(*a > 0.0))
            throw UsageError("--bearing-area " + args.text("bearing-area") +
                             ": must be > 0 (in^2)");
        o.bearingAreaIn2 = *a;
    }
    o.fit.alpha = args.number("alpha", 2.0);
    if (o.fit.alpha != 0.0 && o.fit.alpha != 2.0)
        throw UsageError("--alpha " + args.text("alpha") +
                         ": must be 0 or 2 (Furgerson 1980 Eq. 3)");
    const std::string beta = args.choice("beta", {"best", "0", "1/3"}, "best");
    if (beta == "0") o.betas = {0.0};
    if (beta == "1/3") o.betas = {1.0 / 3.0};
    o.maxCpPsi = args.number("max-cp", 400.0);
    if (!(o.maxCpPsi > 0.0))
        throw UsageError("--max-cp " + args.text("max-cp") + ": must be > 0 (psi)");
    o.outlierAlpha = args.number("outlier-alpha", 0.05);
    if (!(o.outlierAlpha > 0.0 && o.outlierAlpha < 0.5))
        throw UsageError("--outlier-alpha " + args.text("outlier-alpha") + ": must be in (0, 0.5)");
    o.outlierMinRuns = args.integer("outlier-min-runs", o.outlierMinRuns);
    if (o.outlierMinRuns < 3)
        throw UsageError("--outlier-min-runs " + args.text("outlier-min-runs") +
                         ": must be at least 3");
    o.excludeOutliers = !args.has("keep-outliers");
    return o;
}

} // namespace

int runFriction(const ArgList& argv) {
    const Args args(argv,
                    {"data", "bearing-area", "alpha", "beta", "max-cp", "outlier-alpha",
                     "outlier-min-runs", "o"},
                    {"keep-outliers"});
    const auto path = args.optionalText("data");
    if (!path) throw UsageError("missing required flag --data FILE.csv");
    const CalibrationOptions options = optionsFromFlags(args);
    std::vector<TripletCurve> runs;
    try {
        runs = readTripletCsv(*path);
    } catch (const TripletCsvError& e) {
        throw UsageError(std::string("--data ") + e.what());
    }
    FrictionCalibration cal;
    try {
        cal = calibrateFriction(runs, options);
    } catch (const std::invalid_argument& e) {
        throw UsageError(std::string("--data ") + *path + ": " + e.what());
    }
    nlohmann::json j = frictionCalibrationJson(cal);
    j["data"] = *path;
    writeOutput(args, "o", jsonText(j, 2) + "\n");
    return 0;
}

} // namespace kinstab::cli
