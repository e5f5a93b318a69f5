// SPDX-License-Identifier: GPL-3.0-or-later
// kinstab-cli record: what a record file holds (docs/theory.md §7) — summary, Fourier amplitude
// spectrum peaks of the ground (and floor) motion and the envelope fitted over |floor acc| (Figs.
// 25-27) — and its catalogue numbers (PGA, PGV, PGD, Arias intensity, D5-95, mean period,
// Sa(T, 5 %) at --sa-period or the floor period: core/excitation/RecordMetrics.h).

#include "app/cli/Args.h"
#include "app/cli/Commands.h"
#include "app/cli/RecordFlags.h"
#include "core/excitation/EnvelopeFit.h"
#include "core/excitation/FourierSpectrum.h"
#include "core/excitation/RecordMetrics.h"
#include "core/io/JsonText.h"
#include "core/io/RecordMetricsJson.h"
#include "core/io/ResultJson.h"

#include <iostream>
#include <sstream>

namespace kinstab::cli {

namespace {

std::string spectraCsv(const AmplitudeSpectrum& ground, const AmplitudeSpectrum* floor) {
    std::ostringstream out;
    out.precision(10);
    out << "frequency_hz,ground" << (floor ? ",floor" : "") << "\n";
    for (std::size_t k = 0; k < ground.frequency.size(); ++k) {
        out << ground.frequency[k] << "," << ground.amplitude[k];
        if (floor) out << "," << (k < floor->amplitude.size() ? floor->amplitude[k] : 0.0);
        out << "\n";
    }
    return out.str();
}

// Sa at the building's period: --sa-period, else the floor filter's period when given.
std::optional<double> saPeriodFromFlags(const Args& args,
                                        const std::optional<FloorFilterParams>& filter) {
    if (!args.has("sa-period"))
        return filter ? std::optional<double>(filter->period) : std::nullopt;
    const double saPeriod = args.number("sa-period", 1.0);
    const FloorFilterParams p{saPeriod, kSpectralDamping, 0.0};
    if (const std::string e = validateFloorFilter(p); !e.empty())
        throw UsageError("--sa-period " + args.text("sa-period") + ": " + e);
    return saPeriod;
}

} // namespace

int runRecord(const ArgList& argv) {
    std::set<std::string> flags = recordReadFlagNames();
    flags.insert({"file", "floor-period", "damping", "peaks", "spectrum-csv", "sa-period"});
    const Args args(argv, flags);
    if (!args.has("file")) throw UsageError("--file: required (the accelerogram to read)");
    const int count = args.integer("peaks", 5);
    if (count < 1 || count > 1000)
        throw UsageError("--peaks " + args.text("peaks") + ": must be between 1 and 1000");
    const Accelerogram ground = readRecordFromFlag(args, "file");
    const std::optional<FloorFilterParams> filter = floorFilterFromFlags(args);

    nlohmann::json j;
    j["record"] = accelerogramJson(ground);
    j["metrics"] = recordMetricsJson(recordMetrics(ground, saPeriodFromFlags(args, filter)));
    const AmplitudeSpectrum sg = amplitudeSpectrum(ground.samples, ground.dt);
    j["spectrum"] = spectrumJson(sg, static_cast<std::size_t>(count));
    j["floor"] = nullptr;
    std::optional<AmplitudeSpectrum> sf;
    if (filter) {
        // Same transform length as the ground spectrum: the floor motion without its tail.
        FloorFilterParams noTail = *filter;
        noTail.tail = 0.0;
        const Accelerogram floorSame = floorMotion(ground, noTail);
        sf = amplitudeSpectrum(floorSame.samples, ground.dt);
        const Accelerogram floor = floorMotion(ground, *filter);
        j["floor"] = {{"filter", floorFilterJson(*filter)},
                      {"peak_g", floor.peak().value},
                      {"peak_time_s", floor.peak().time},
                      {"npts", floor.size()},
                      {"spectrum", spectrumJson(*sf, static_cast<std::size_t>(count))},
                      {"energy_near_1_over_T",
                       bandEnergyFraction(*sf, 0.8 / filter->period, 1.2 / filter->period)}};
        j["envelope"] = envelopeFitJson(floor);
        j["envelope"]["of"] = "floor";
    } else {
        j["envelope"] = envelopeFitJson(ground);
        j["envelope"]["of"] = "ground";
    }
    if (args.has("spectrum-csv"))
        writeOutput(args, "spectrum-csv", spectraCsv(sg, sf ? &*sf : nullptr));
    std::cout << jsonText(j, 2) << "\n";
    return 0;
}

} // namespace kinstab::cli
