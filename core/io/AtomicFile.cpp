// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/io/AtomicFile.h"

#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <random>
#include <sstream>
#include <sys/stat.h>
#include <unistd.h>

namespace kinstab {

namespace {

// The reason in English whatever the locale (a GUI or report run sets the user's locale), so
// that messages and logs read the same everywhere. strerrordesc_np: glibc 2.32 and later.
std::string reason(int error) {
    const char* text = ::strerrordesc_np(error);
    return text ? text : "error " + std::to_string(error);
}

[[noreturn]] void fail(const std::string& path, int error) {
    throw WriteError("cannot write " + path + ": " + reason(error));
}

// Writes all bytes, retrying short writes and interrupted calls; returns 0 or the errno.
int writeAll(int fd, std::string_view bytes) {
    std::size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) return errno;
        if (n == 0) return EIO; // no progress: stop rather than loop for ever
        done += static_cast<std::size_t>(n);
    }
    return 0;
}

std::string folderOf(const std::string& path) {
    const auto slash = path.rfind('/');
    if (slash == std::string::npos) return ".";
    return slash == 0 ? "/" : path.substr(0, slash);
}

std::string randomSuffix() {
    static thread_local std::mt19937_64 engine{std::random_device{}()};
    const char* digits = "0123456789abcdefghijklmnopqrstuvwxyz";
    std::string s(12, '0');
    for (char& c : s)
        c = digits[engine() % 36];
    return s;
}

// Creates a fresh temporary file next to target; sets tmp to its name. O_EXCL with O_NOFOLLOW
// fails on anything already at that name, symlinks included, so nothing planted is followed.
int createTemporary(const std::string& target, std::string& tmp) {
    const std::string folder = folderOf(target);
    const std::string base = target.substr(target.rfind('/') + 1);
    for (int attempt = 0; attempt < 64; ++attempt) { // a clash is 1 in 36^12: 64 is plenty
        tmp = folder + "/." + base + "." + randomSuffix() + ".tmp";
        const int fd =
            ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
        if (fd >= 0 || errno != EEXIST) return fd;
    }
    errno = EEXIST;
    return -1;
}

// /dev/null, a FIFO, a terminal: no temporary file and no rename, the bytes go straight in.
void writeStraightThrough(const std::string& path, std::string_view bytes) {
    const int fd = ::open(path.c_str(), O_WRONLY | O_CLOEXEC);
    if (fd < 0) fail(path, errno);
    const int error = writeAll(fd, bytes);
    const int closed = ::close(fd) == 0 ? 0 : errno;
    if (error != 0 || closed != 0) fail(path, error != 0 ? error : closed);
}

// The rename is durable only once the folder's entry is on disk. A failure here comes after
// the new file is already in place, so it is not reported as a failed write.
void syncFolder(const std::string& folder) {
    const int fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0) return;
    ::fsync(fd);
    ::close(fd);
}

// The path the new file is renamed to: the target itself, or for a symlink the file it names.
std::string renameTarget(const std::string& path) {
    struct stat link {};
    if (::lstat(path.c_str(), &link) != 0 || !S_ISLNK(link.st_mode)) return path;
    char resolved[PATH_MAX];
    if (::realpath(path.c_str(), resolved) == nullptr) return path; // dangling: replace the link
    return resolved;
}

} // namespace

void writeFileAtomically(const std::string& path, std::string_view bytes) {
    if (path.empty()) throw WriteError("cannot write a file with an empty name");
    struct stat existing {};
    const bool exists = ::stat(path.c_str(), &existing) == 0;
    if (exists && S_ISDIR(existing.st_mode)) fail(path, EISDIR);
    if (exists && !S_ISREG(existing.st_mode)) return writeStraightThrough(path, bytes);

    const std::string target = renameTarget(path);
    std::string tmp;
    const int fd = createTemporary(target, tmp);
    if (fd < 0) fail(path, errno);
    int error = writeAll(fd, bytes);
    if (error == 0 && exists) ::fchmod(fd, existing.st_mode & 07777); // keep the old mode
    if (error == 0 && ::fsync(fd) != 0) error = errno;
    if (::close(fd) != 0 && error == 0) error = errno;
    if (error == 0 && ::rename(tmp.c_str(), target.c_str()) != 0) error = errno;
    if (error != 0) {
        ::unlink(tmp.c_str());
        fail(path, error);
    }
    syncFolder(folderOf(target));
}

void writeStandardOutput(std::string_view bytes) {
    std::cout.flush(); // what was printed before goes first
    const std::size_t n = std::fwrite(bytes.data(), 1, bytes.size(), stdout);
    const int error = errno;
    if (n != bytes.size()) throw WriteError("cannot write standard output: " + reason(error));
    flushStandardOutput();
}

void flushStandardOutput() {
    errno = 0;
    std::cout.flush(); // std::cout writes through stdio: this flushes stdout and may fail here
    int error = errno;
    const bool flushed = std::fflush(stdout) == 0;
    if (error == 0) error = errno != 0 ? errno : EIO;
    if (!flushed || std::ferror(stdout) || !std::cout)
        throw WriteError("cannot write standard output: " + reason(error));
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
