// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/base/LineReader.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace kinstab {

namespace {

// The reason in English whatever the locale, as core/io/AtomicFile.cpp writes it.
std::string reason(int error) {
    const char* text = ::strerrordesc_np(error);
    return text ? text : "error " + std::to_string(error);
}

} // namespace

LineReader::LineReader(std::string path, std::size_t maxLineBytes, std::size_t chunk)
    : path_(std::move(path)), maxLine_(maxLineBytes), chunk_(chunk < 1 ? 1 : chunk) {
    if (path_.find('\0') != std::string::npos)
        throw LineReadError("the path contains a NUL character");
    fd_ = ::open(path_.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd_ < 0) throw LineReadError("cannot be opened: " + reason(errno));
    struct stat st {};
    if (::fstat(fd_, &st) != 0 || S_ISDIR(st.st_mode)) {
        const int error = S_ISDIR(st.st_mode) ? EISDIR : errno;
        ::close(fd_);
        fd_ = -1;
        throw LineReadError("cannot be read: " + reason(error));
    }
    regular_ = S_ISREG(st.st_mode);
    device_ = st.st_dev;
    inode_ = st.st_ino;
}

LineReader::~LineReader() {
    if (fd_ >= 0) ::close(fd_);
}

void LineReader::suspend() {
    if (!regular_ || fd_ < 0) return;
    ::close(fd_);
    fd_ = -1;
}

// The same file (device and inode) as first opened: a file replaced meanwhile is an error.
void LineReader::reopen() {
    fd_ = ::open(path_.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd_ < 0) throw LineReadError("cannot be opened again: " + reason(errno));
    struct stat st {};
    if (::fstat(fd_, &st) != 0 || st.st_dev != device_ || st.st_ino != inode_)
        throw LineReadError("was replaced while it was read");
}

bool LineReader::fill() {
    if (ended_) return false;
    if (fd_ < 0) reopen();
    // What was handed out is dropped first, so the buffer holds at most a line and a chunk.
    buffer_.erase(0, position_);
    position_ = 0;
    const std::size_t old = buffer_.size();
    buffer_.resize(old + chunk_);
    // Bounded: each pass either reads bytes, ends, fails, or retries an interrupted call.
    for (;;) {
        const ssize_t n =
            regular_ ? ::pread(fd_, buffer_.data() + old, chunk_, static_cast<off_t>(readOffset_))
                     : ::read(fd_, buffer_.data() + old, chunk_);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) {
            const int error = errno;
            buffer_.resize(old);
            const std::string where =
                lineNumber_ == 0 ? "" : " after line " + std::to_string(lineNumber_);
            throw LineReadError("cannot be read" + where + ": " + reason(error) +
                                " (a read error, not the end of the file)");
        }
        buffer_.resize(old + static_cast<std::size_t>(n));
        readOffset_ += static_cast<std::uint64_t>(n);
        if (n == 0) ended_ = true;
        return n > 0;
    }
}

bool LineReader::take(std::string& line, std::size_t length, bool ended) {
    if (length > maxLine_)
        throw LineReadError("line " + std::to_string(lineNumber_ + 1) +
                            " is longer than the limit of " + std::to_string(maxLine_) + " bytes");
    line.assign(buffer_, position_, length);
    lastLineEnded_ = ended;
    position_ += length + (ended ? 1 : 0);
    lineEnd_ += length + (ended ? 1 : 0);
    ++lineNumber_;
    return true;
}

bool LineReader::next(std::string& line) {
    std::size_t searched = position_;
    // Each pass reads a chunk or returns: at most maxLine / chunk + 2 passes per line.
    for (;;) {
        const std::size_t end = buffer_.find('\n', searched);
        if (end != std::string::npos) return take(line, end - position_, true);
        const std::size_t pending = buffer_.size() - position_;
        if (pending > maxLine_) return take(line, pending, false);     // throws: too long
        if (!fill()) return pending > 0 && take(line, pending, false); // the end of the file
        searched = pending; // fill() moved the unread bytes to the front
    }
}

} // namespace kinstab
