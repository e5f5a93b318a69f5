#include "core/io/AtomicFile.h"

#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace kinstab {

namespace {
std::string temporaryName(const std::string& path) {
    // Unique per call, so two saves racing in one process never share a temporary file.
    static std::atomic<unsigned long> counter{0};
    const auto now = std::chrono::steady_clock::now().time_since_epoch().count();
    return path + ".tmp-" + std::to_string(now) + "-" + std::to_string(counter++);
}
} // namespace

void writeFileAtomically(const std::string& path, const std::string& text) {
    if (path.empty()) throw FileError("file name is empty");
    const std::string tmp = temporaryName(path);
    {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        if (!out) throw FileError(path + ": cannot write in this directory");
        out << text;
        out.flush();
        if (!out) {
            out.close();
            std::error_code ignored;
            std::filesystem::remove(tmp, ignored);
            throw FileError(path + ": write failed (disk full?)");
        }
    }
    std::error_code ec;
    std::filesystem::rename(tmp, path, ec);
    if (ec) {
        std::error_code ignored;
        std::filesystem::remove(tmp, ignored);
        throw FileError(path + ": " + ec.message());
    }
}

std::string readWholeFile(const std::string& path) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) throw FileError(path + ": is a directory");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw FileError(path + ": cannot open this file");
    std::ostringstream s;
    s << in.rdbuf();
    if (in.bad()) throw FileError(path + ": read failed");
    return s.str();
}

} // namespace kinstab
