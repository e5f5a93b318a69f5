// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/io/AtomicFile.h"

#include <cctype>
#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <dirent.h>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <random>
#include <sstream>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>

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
// removal (when given) arms the name before the file exists, so that no signal between creating
// and arming leaves it behind; a name nothing else can guess is ours once open() succeeds.
int createTemporary(const std::string& target, std::string& tmp,
                    std::optional<RemovedOnSignal>* removal) {
    const std::string folder = folderOf(target);
    const std::string base = target.substr(target.rfind('/') + 1);
    for (int attempt = 0; attempt < 64; ++attempt) { // a clash is 1 in 36^12: 64 is plenty
        tmp = folder + "/." + base + "." + randomSuffix() + ".tmp";
        if (removal) removal->emplace(tmp);
        const int fd =
            ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
        if (fd >= 0) return fd;
        const int error = errno;
        if (removal) removal->reset(); // not ours: never to be removed
        errno = error;
        if (error != EEXIST) return -1;
    }
    errno = EEXIST;
    return -1;
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

// ".NAME." 12 characters of [0-9a-z] ".tmp": the name createTemporary gives.
bool isTemporaryOf(const std::string& name, const std::string& base) {
    const std::string prefix = "." + base + ".";
    if (name.size() != prefix.size() + 12 + 4 || name.rfind(prefix, 0) != 0) return false;
    if (name.compare(name.size() - 4, 4, ".tmp") != 0) return false;
    for (std::size_t i = prefix.size(); i < prefix.size() + 12; ++i)
        if (!std::isdigit(static_cast<unsigned char>(name[i])) &&
            !std::islower(static_cast<unsigned char>(name[i])))
            return false;
    return true;
}

} // namespace

AtomicFileWriter::AtomicFileWriter(const std::string& path, Unfinished unfinished)
    : path_(path), keep_(unfinished == Unfinished::Keep) {
    if (path.empty()) throw WriteError("cannot write a file with an empty name");
    if (path.find('\0') != std::string::npos)
        throw WriteError("cannot write " + path + ": the path contains a NUL character");
    struct stat existing {};
    const bool exists = ::stat(path.c_str(), &existing) == 0;
    if (exists && S_ISDIR(existing.st_mode)) fail(path, EISDIR);
    if (exists && !S_ISREG(existing.st_mode)) { // /dev/null, a FIFO: no temporary, no rename
        fd_ = ::open(path.c_str(), O_WRONLY | O_CLOEXEC);
        if (fd_ < 0) fail(path, errno);
        return;
    }
    target_ = renameTarget(path);
    fd_ = createTemporary(target_, temporary_, keep_ ? nullptr : &removal_);
    if (fd_ < 0) fail(path, errno);
    ::flock(fd_, LOCK_EX | LOCK_NB); // new and unpredictable: nobody else holds it
}

std::unique_ptr<AtomicFileWriter> AtomicFileWriter::adopt(const std::string& path,
                                                          const std::string& temporary) {
    std::unique_ptr<AtomicFileWriter> w(new AtomicFileWriter());
    w->fd_ = ::open(temporary.c_str(), O_RDWR | O_NOFOLLOW | O_CLOEXEC);
    if (w->fd_ < 0) return nullptr;
    struct stat st {};
    // Another user's file, or a second name of some other file, is not a leftover to write to.
    if (::fstat(w->fd_, &st) != 0 || !S_ISREG(st.st_mode) || st.st_uid != ::geteuid() ||
        st.st_nlink != 1)
        return nullptr; // ~AtomicFileWriter closes it; temporary_ is empty: nothing removed
    if (::flock(w->fd_, LOCK_EX | LOCK_NB) != 0 && errno == EWOULDBLOCK) return nullptr;
    w->path_ = path;
    w->target_ = renameTarget(path);
    w->temporary_ = temporary;
    w->keep_ = true;
    return w;
}

std::vector<std::string> AtomicFileWriter::leftovers(const std::string& path) {
    const std::string target = renameTarget(path);
    const std::string folder = folderOf(target);
    const std::string base = target.substr(target.rfind('/') + 1);
    std::vector<std::string> found;
    DIR* dir = ::opendir(folder.c_str());
    if (!dir) return found;
    // One pass per folder entry: bounded by the folder's size.
    while (const dirent* e = ::readdir(dir))
        if (isTemporaryOf(e->d_name, base)) found.push_back(folder + "/" + e->d_name);
    ::closedir(dir);
    std::sort(found.begin(), found.end());
    return found;
}

AtomicFileWriter::~AtomicFileWriter() {
    if (fd_ >= 0) ::close(fd_);
    if (!temporary_.empty() && !keep_) ::unlink(temporary_.c_str());
}

void AtomicFileWriter::write(std::string_view bytes) {
    if (const int error = writeAll(fd_, bytes); error != 0) fail(path_, error);
}

void AtomicFileWriter::truncate(std::uint64_t bytes) {
    if (::ftruncate(fd_, static_cast<off_t>(bytes)) != 0 ||
        ::lseek(fd_, static_cast<off_t>(bytes), SEEK_SET) < 0)
        fail(path_, errno);
}

std::uint64_t AtomicFileWriter::size() const {
    struct stat st {};
    return ::fstat(fd_, &st) == 0 ? static_cast<std::uint64_t>(st.st_size) : 0;
}

void AtomicFileWriter::commit() {
    const bool straight = temporary_.empty();
    int error = 0;
    struct stat old {};
    // A file that was there keeps its mode; a new one has 0666 less the umask.
    if (!straight && ::stat(target_.c_str(), &old) == 0) ::fchmod(fd_, old.st_mode & 07777);
    if (!straight && ::fsync(fd_) != 0) error = errno;
    if (::close(fd_) != 0 && error == 0) error = errno;
    fd_ = -1;
    if (error != 0) fail(path_, error);
    if (straight) return;
    if (::rename(temporary_.c_str(), target_.c_str()) != 0) fail(path_, errno);
    // Disarmed after the rename: a signal between the two unlinks a name that no longer exists.
    if (removal_) removal_->disarm();
    temporary_.clear();
    syncFolder(folderOf(target_));
}

void AtomicFileWriter::discard() {
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
    if (!temporary_.empty()) ::unlink(temporary_.c_str());
    temporary_.clear();
}

void writeFileAtomically(const std::string& path, std::string_view bytes) {
    AtomicFileWriter w(path);
    w.write(bytes);
    w.commit();
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
