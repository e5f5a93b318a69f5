// SPDX-License-Identifier: GPL-3.0-or-later
// kinstab-cli rocking-map: the overturning map of a pulse shape over a_p / (alpha g) and
// omega_p / p (Zhang & Makris 2001; core/rocking/OverturningMap.h), as JSON or CSV.

#include "app/cli/Args.h"
#include "app/cli/Commands.h"
#include "app/cli/RockingFlags.h"
#include "core/io/JsonText.h"
#include "core/io/RockingJson.h"
#include "core/rocking/OverturningMap.h"

#include <chrono>
#include <sstream>

namespace kinstab::cli {

namespace {

// MIN,MAX of an axis, both > 0, MIN <= MAX.
std::pair<double, double> rangeFlag(const Args& args, const std::string& flag, double lo,
                                    double hi) {
    if (!args.has(flag)) return {lo, hi};
    const std::vector<double> v = args.list(flag);
    if (v.size() != 2 || !(v[0] > 0.0) || !(v[1] >= v[0]) || !(v[1] <= 1e4))
        throw UsageError("--" + flag + " " + args.text(flag) +
                         ": must be MIN,MAX with 0 < MIN <= MAX <= 10000");
    return {v[0], v[1]};
}

int pointsFlag(const Args& args, const std::string& flag, int fallback) {
    const int n = args.integer(flag, fallback);
    if (n < 1 || n > 4097)
        throw UsageError("--" + flag + " " + args.text(flag) + ": must be 1 to 4097");
    return n;
}

std::string mapCsv(const OverturningMap& m) {
    std::ostringstream s;
    s.imbue(std::locale::classic());
    s.precision(10);
    s << "omega_p_over_p,a_p_over_alpha_g,state,max_theta_over_alpha\n";
    static const char* kState[] = {"survives", "overturns", "leaves-base"};
    for (std::size_t i = 0; i < m.frequencies.size(); ++i)
        for (std::size_t j = 0; j < m.amplitudes.size(); ++j) {
            const std::size_t k = m.at(static_cast<int>(i), static_cast<int>(j));
            s << m.frequencies[i] << ',' << m.amplitudes[j] << ',' << kState[m.overturns[k]] << ','
              << m.maxThetaOverAlpha[k] << '\n';
        }
    return s.str();
}

} // namespace

int runRockingMap(const ArgList& argv) {
    std::set<std::string> flags = rockingModelFlagNames();
    flags.insert({"pulse", "amplitudes", "frequencies", "points", "amplitude-points",
                  "frequency-points", "threads", "format", "o"});
    const Args args(argv, flags, {"linear"});
    const RockingModel m = rockingModelFromFlags(args);
    for (const char* f : {"mu", "initial-tilt", "duration"})
        if (args.has(f))
            throw UsageError(std::string("--") + f + " " + args.text(f) +
                             ": the map is of a block rocking on a base that holds it, from rest");
    if (args.has("o")) checkOutputPath("o", args.text("o"));
    OverturningMapSpec s;
    s.shape = *pulseShapeFromName(
        args.choice("pulse", {"half-sine", "one-sine", "one-cosine", "rectangular"}, "one-sine"));
    std::tie(s.amplitudeMin, s.amplitudeMax) = rangeFlag(args, "amplitudes", 0.5, 10.0);
    std::tie(s.frequencyMin, s.frequencyMax) = rangeFlag(args, "frequencies", 0.5, 10.0);
    const int n = pointsFlag(args, "points", 101);
    s.amplitudePoints = pointsFlag(args, "amplitude-points", n);
    s.frequencyPoints = pointsFlag(args, "frequency-points", n);
    s.threads = args.integer("threads", 0);
    if (s.threads < 0 || s.threads > 1024)
        throw UsageError("--threads " + args.text("threads") + ": must be 0 (all) to 1024");
    const std::string format = args.choice("format", {"json", "csv"}, "json");
    const auto start = std::chrono::steady_clock::now();
    const OverturningMap map = overturningMap(m, s);
    if (format == "csv") {
        writeOutput(args, "o", mapCsv(map));
        return 0;
    }
    nlohmann::json j = overturningMapJson(map);
    j["block"] = rockingModelJson(m);
    j["wall_time_s"] =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    writeOutput(args, "o", jsonText(j, 1) + "\n");
    return 0;
}

} // namespace kinstab::cli
