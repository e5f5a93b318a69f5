// SPDX-License-Identifier: GPL-3.0-or-later
// kinstab-cli report: the report draws with Qt Gui, which no other command needs; loading Qt was
// 96 % of a compute command's start (issue 34). The report lives in kinstab-report, which runs in
// this process's place (execv): the same arguments, standard streams, exit code and signals, so
// the user still sees one program.

#include "app/cli/Commands.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <vector>

namespace kinstab::cli {

namespace {
// Beside this executable (the build tree, or a folder that holds both), else where the install
// puts it relative to this one (KINSTAB_REPORT_FROM_BIN, app/CMakeLists.txt).
std::vector<std::filesystem::path> reportCandidates() {
    std::error_code ec;
    const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (ec) return {};
    const std::filesystem::path dir = self.parent_path();
    return {dir / "kinstab-report", (dir / KINSTAB_REPORT_FROM_BIN).lexically_normal()};
}
} // namespace

int runReport(const ArgList& args) {
    std::vector<std::string> words{"kinstab-report"};
    words.insert(words.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (std::string& w : words)
        argv.push_back(w.data());
    argv.push_back(nullptr);
    std::string tried;
    int error = ENOENT;
    for (const std::filesystem::path& path : reportCandidates()) {
        ::execv(path.c_str(), argv.data()); // returns only when it could not run
        error = errno;
        tried += (tried.empty() ? "" : ", ") + path.string();
    }
    throw std::runtime_error("cannot run kinstab-report, the program that writes reports (" +
                             (tried.empty() ? std::string("/proc/self/exe unreadable") : tried) +
                             "): " + std::strerror(error));
}

} // namespace kinstab::cli
