// SPDX-License-Identifier: GPL-3.0-or-later
// kinstab-cli fragility: lognormal collapse fragility per parameter set from study rows
// (docs/studies.md).

#include "app/cli/Args.h"
#include "app/cli/Commands.h"
#include "core/base/TextInput.h"
#include "core/io/FragilityText.h"
#include "core/io/JsonText.h"
#include "core/io/StudyResults.h"
#include "core/study/CpuAffinity.h"

namespace kinstab::cli {

int runFragility(const ArgList& argv) {
    const Args args(argv, {"results", "format", "bootstrap", "seed", "level", "threads", "o"});
    const std::string results = args.text("results");
    if (results.empty()) throw UsageError("missing required flag --results");
    const std::string format = args.choice("format", {"json", "csv"}, "json");
    BootstrapSettings b;
    const std::string resamples = args.text("bootstrap", "1000");
    const auto n = parseCount(resamples, 100'000);
    if (!n) throw UsageError("--bootstrap " + quotedToken(resamples) + ": must be 0 to 100000");
    b.resamples = *n;
    const std::string seed = args.text("seed", "1");
    const auto s = parseCount(seed, 1'000'000'000'000ull);
    if (!s) throw UsageError("--seed " + quotedToken(seed) + ": must be a whole number >= 0");
    b.seed = *s;
    b.level = args.number("level", 0.90);
    if (!(b.level > 0.0 && b.level < 1.0))
        throw UsageError("--level " + args.text("level") + ": must be > 0 and < 1");
    b.threads = static_cast<int>(allowedCpuCount());
    if (args.has("threads")) {
        const std::string t = args.text("threads");
        const auto n = parseCount(t, 1024);
        if (!n || *n < 1) throw UsageError("--threads " + quotedToken(t) + ": must be 1 to 1024");
        b.threads = static_cast<int>(*n);
    }
    if (const auto o = args.optionalText("o")) checkOutputPath("o", *o);
    // One parameter set's rows in memory at a time (the file is in case order).
    std::vector<Fragility> sets;
    try {
        forEachStudySet(
            results, [&](std::vector<StudyRow>&& rows) { sets.push_back(fragilityOf(rows, b)); });
    } catch (const StudyRowError& e) {
        throw UsageError("--results " + std::string(e.what()));
    } catch (const StudyError& e) { // the bootstrap's bound on its work (core/study/Fragility.h)
        throw UsageError("--bootstrap " + resamples + ": " + e.what());
    }
    std::string text;
    if (format == "csv") {
        text = fragilityCsv(sets);
    } else {
        text = jsonText(fragilityJson(sets, b), 2) + "\n";
    }
    writeOutput(args, "o", text);
    return 0;
}

} // namespace kinstab::cli
