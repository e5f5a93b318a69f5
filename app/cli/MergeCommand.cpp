// SPDX-License-Identifier: GPL-3.0-or-later
// kinstab-cli merge: shards of a study into the file one unsharded run writes (docs/studies.md).

#include "app/cli/Args.h"
#include "app/cli/Commands.h"
#include "app/cli/StreamedOutput.h"
#include "core/base/TextInput.h"
#include "core/io/StudyResults.h"

#include <sys/resource.h>

#include <sstream>

namespace kinstab::cli {

namespace {

// A file naming the shards, one per line (a job array's thousands of shards do not fit on a
// command line).
void addListed(const std::string& list, std::vector<std::string>& shards) {
    const FileText f = readTextFile(list, 64u * 1024u * 1024u);
    if (!f.error.empty()) throw UsageError("--list " + list + ": " + f.error);
    std::string line;
    std::istringstream in{f.text};
    while (std::getline(in, line))
        if (!line.empty()) shards.push_back(line);
}

// Every shard's descriptor held at once where the hard open-file limit allows (a job array's
// shards outnumber the usual soft limit of 1024); beyond it the merge reads shards in turn
// (core/io/ShardPool.h).
void raiseOpenFileLimit() {
    rlimit limit{};
    if (::getrlimit(RLIMIT_NOFILE, &limit) != 0 || limit.rlim_cur >= limit.rlim_max) return;
    limit.rlim_cur = limit.rlim_max;
    ::setrlimit(RLIMIT_NOFILE, &limit);
}

} // namespace

int runMerge(const ArgList& argv) {
    std::vector<std::string> shards, lists;
    std::optional<std::string> output;
    for (std::size_t i = 0; i < argv.size(); ++i) {
        const std::string& a = argv[i];
        const bool takesValue = a == "-o" || a == "--list";
        if (takesValue && i + 1 >= argv.size()) throw UsageError("flag " + a + " needs a value");
        if (a == "-o") {
            if (output) throw UsageError("flag -o given twice");
            output = argv[++i];
        } else if (a == "--list") {
            lists.push_back(argv[++i]); // read once every flag is known to be good
        } else if (a.rfind("-", 0) == 0 && a != "-") {
            throw UsageError("unknown flag " + quotedToken(a));
        } else {
            shards.push_back(a);
        }
    }
    for (const std::string& l : lists)
        addListed(l, shards);
    if (shards.empty()) throw UsageError("no shards to merge: name the shard files");
    if (!output) throw UsageError("missing required flag -o (use - for stdout)");
    checkOutputPath("o", *output);
    raiseOpenFileLimit();
    // Rows go to a temporary file renamed into place at the end: a refused merge leaves no file.
    StreamedOutput out(*output);
    try {
        mergeStudyShards(shards, [&out](std::string_view rows) { out.write(rows); });
    } catch (const StudyRowError& e) {
        throw UsageError(e.what());
    }
    out.commit();
    return 0;
}

} // namespace kinstab::cli
