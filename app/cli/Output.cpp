// SPDX-License-Identifier: GPL-3.0-or-later
// Every file kinstab-cli writes goes through here: stdout for "-" (or no -o), otherwise the
// atomic writer of core/io/AtomicFile.h. A bad name is a UsageError (exit 2) found before any
// work; a write that fails (full disk, full stdout) is a WriteError (exit 3).

#include "app/cli/Args.h"
#include "app/cli/Commands.h"
#include "core/io/AtomicFile.h"

#include <filesystem>

namespace kinstab::cli {

namespace {
std::string flagLabel(const std::string& flag) {
    return flag == "o" ? "-o" : "--" + flag;
}
} // namespace

void checkOutputPath(const std::string& flag, const std::string& path) {
    const std::string label = flagLabel(flag);
    if (path.empty()) throw UsageError(label + " \"\": the file name is empty (use - for stdout)");
    if (path == "-") return;
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec))
        throw UsageError(label + " " + path + ": is a folder, not a file");
    const std::filesystem::path dir = std::filesystem::absolute(path, ec).parent_path();
    if (!std::filesystem::is_directory(dir, ec))
        throw UsageError(label + " " + path + ": the folder " + dir.string() + " does not exist");
}

void writeOutput(const Args& args, const std::string& flag, const std::string& text) {
    const std::optional<std::string> path = args.optionalText(flag);
    if (path) checkOutputPath(flag, *path);
    if (!path || *path == "-")
        writeStandardOutput(text);
    else
        writeFileAtomically(*path, text);
}

} // namespace kinstab::cli
