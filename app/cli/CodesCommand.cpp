// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli/Args.h"
#include "app/cli/BuildingFlags.h"
#include "app/cli/Commands.h"
#include "core/io/CodesJson.h"
#include "core/io/JsonText.h"

#include <iostream>

namespace kinstab::cli {

int runCodes(const ArgList& argv) {
    const Args args(argv, buildingFlagNames(), buildingSwitchNames());
    Building building;
    CodeSelection codes;
    if (args.has("project")) {
        for (const std::string& f : buildingFlagNames())
            if (f != "project" && args.has(f))
                throw UsageError("--" + f + ": building flags and --project exclude each other");
        if (args.has("irregular"))
            throw UsageError("--irregular: building flags and --project exclude each other");
        const Project p = projectFromFlag(args);
        if (p.codes.empty())
            throw UsageError("--project " + args.text("project") + ": the project selects no code");
        building = p.building;
        codes = p.codes;
    } else {
        building = buildingFromFlags(args);
        codes = codesFromFlags(args);
    }
    try {
        std::cout << jsonText(codeResultsJson(kinstab::runCodes(building, codes)), 2) << "\n";
    } catch (const InputError& e) {
        throw inputUsageError(e);
    }
    return 0;
}

} // namespace kinstab::cli
