// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli/StreamedOutput.h"

#include "core/io/AtomicFile.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <vector>

namespace kinstab::cli {

namespace {
[[noreturn]] void fail(const std::string& path, int err) {
    throw WriteError("cannot write " + path + ": " + std::strerror(err));
}
} // namespace

StreamedOutput::StreamedOutput(const std::string& path) : path_(path) {
    if (path.empty() || path == "-") return;
    struct stat st {};
    // A device or FIFO (/dev/null) is written straight through, never replaced by a file.
    if (::stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode)) {
        fd_ = ::open(path.c_str(), O_WRONLY | O_CLOEXEC);
        if (fd_ < 0) fail(path, errno);
        return;
    }
    // The mode an ordinary new file gets (0666 less the umask), or the one the target has.
    const mode_t mask = ::umask(0);
    ::umask(mask);
    mode_ = ::stat(path.c_str(), &st) == 0 ? (st.st_mode & 07777) : (0666 & ~mask);
    temp_ = path + ".partial-XXXXXX";
    std::vector<char> name(temp_.begin(), temp_.end());
    name.push_back('\0');
    fd_ = ::mkstemp(name.data()); // O_CREAT | O_EXCL with an unpredictable name
    if (fd_ < 0) fail(path, errno);
    temp_ = name.data();
}

StreamedOutput::~StreamedOutput() {
    if (fd_ >= 0) ::close(fd_);
    if (!temp_.empty()) ::unlink(temp_.c_str());
}

void StreamedOutput::write(std::string_view bytes) {
    if (fd_ < 0) {
        writeStandardOutput(bytes);
        return;
    }
    while (!bytes.empty()) {
        const ssize_t n = ::write(fd_, bytes.data(), bytes.size());
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) fail(path_, n < 0 ? errno : ENOSPC);
        bytes.remove_prefix(static_cast<std::size_t>(n));
    }
}

void StreamedOutput::commit() {
    if (fd_ < 0) return;
    if (!temp_.empty() && (::fchmod(fd_, mode_) != 0 || ::fsync(fd_) != 0)) fail(path_, errno);
    const int closed = ::close(fd_);
    fd_ = -1;
    if (closed != 0) fail(path_, errno);
    if (temp_.empty()) return;
    if (std::rename(temp_.c_str(), path_.c_str()) != 0) fail(path_, errno);
    temp_.clear();
}

} // namespace kinstab::cli
