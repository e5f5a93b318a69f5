// SPDX-License-Identifier: GPL-3.0-or-later
// kinstab-cli study: the cases of a study file (or of one shard of it) as JSONL rows
// (docs/studies.md).

#include "app/cli/Args.h"
#include "app/cli/Commands.h"
#include "app/cli/ProgressLine.h"
#include "app/cli/StreamedOutput.h"
#include "core/base/TextInput.h"
#include "core/io/AtomicFile.h"
#include "core/io/StudyResume.h"
#include "core/io/StudyRowJson.h"
#include "core/io/StudySpecJson.h"
#include "core/study/CpuAffinity.h"
#include "core/study/StudyRecords.h"
#include "core/study/StudyRunner.h"

#include <atomic>
#include <iostream>
#include <vector>

namespace kinstab::cli {

namespace {

// Worker threads: the CPUs this process may use (a Slurm allocation, taskset) unless told.
unsigned threadCount(const Args& args) {
    if (!args.has("threads")) return allowedCpuCount();
    const std::string t = args.text("threads");
    const auto n = parseCount(t, 1024);
    if (!n || *n < 1) throw UsageError("--threads " + quotedToken(t) + ": must be 1 to 1024");
    return static_cast<unsigned>(*n);
}

Shard shardOf(const Args& args) {
    if (!args.has("shard")) return {};
    const std::string t = args.text("shard");
    const auto s = parseShard(t);
    if (!s) throw UsageError("--shard " + quotedToken(t) + ": must be K/N with 1 <= K <= N");
    return *s;
}

// --resume: the output's temporary file as an interrupted run of this shard left it, or a new
// one; either is kept when this run is interrupted too.
StreamedOutput resumableOutput(const StudySpec& spec, StudyRunOptions& options,
                               const std::string& path) {
    ResumedShard r = resumeShard(spec, options.shard, path);
    if (!r.writer)
        return StreamedOutput(
            std::make_unique<AtomicFileWriter>(path, AtomicFileWriter::Unfinished::Keep));
    options.done = r.done;
    std::cerr << "kinstab-cli study: resuming " << path << " from " << r.writer->temporary() << ": "
              << r.done << " of " << shardCaseCount(spec, options.shard)
              << " cases of the shard done\n";
    return StreamedOutput(std::move(r.writer));
}

} // namespace

int runStudyCommand(const ArgList& argv) {
    const Args args(argv, {"spec", "o", "shard", "threads"}, {"count", "resume"});
    const std::string specPath = args.text("spec");
    if (specPath.empty()) throw UsageError("missing required flag --spec");
    StudyRunOptions options;
    options.shard = shardOf(args);
    options.threads = threadCount(args);
    const std::string output = args.text("o", "-");
    if (args.has("o")) checkOutputPath("o", output);
    if (args.has("resume") && output == "-")
        throw UsageError("--resume needs -o FILE: it continues from that file's temporary file");
    StudySpec spec;
    try {
        spec = loadStudy(specPath);
        if (args.has("count")) {
            writeStandardOutput(std::to_string(studyCaseCount(spec)) + "\n");
            return 0;
        }
        loadStudyRecords(spec); // each record read once, for every case of the study
    } catch (const StudyError& e) {
        throw UsageError("--spec " + specPath + ": " + e.what());
    }
    StreamedOutput out =
        args.has("resume") ? resumableOutput(spec, options, output) : StreamedOutput(output);
    // Rows come in blocks, in case order: the progress counts them as they are written.
    std::atomic<std::size_t> written{0};
    const std::size_t cases = shardCaseCount(spec, options.shard) - options.done;
    {
        const ProgressLine progress("study", "cases",
                                    [&] { return std::pair(written.load(), cases); });
        runStudy(spec, options, [&out, &written](const std::vector<StudyRow>& rows) {
            out.write(studyRowsText(rows));
            written += rows.size();
        });
    }
    out.commit();
    return 0;
}

} // namespace kinstab::cli
