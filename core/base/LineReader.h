// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The lines of a file, read through a buffer of its own (POSIX), for files too large to read
// whole (study results). Two things std::getline cannot tell: a line longer than the limit is
// refused as soon as the limit is passed, never held whole (a 1 GiB "row" must not take 1 GiB),
// and a read that fails (an I/O error) is an error, never taken for the end of the file.
// A regular file's descriptor can be released between lines (suspend) and is reopened where
// reading stopped, checked to be the same file: a merge can read more files than the process
// may hold open at once.

#include <sys/types.h>

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace kinstab {

// "cannot be read: Input/output error", "line 3 is longer than the limit of 65536 bytes", ...
// without the file's name (the caller names it).
struct LineReadError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

class LineReader {
public:
    // Opens the file; throws LineReadError. chunk: bytes read at a time (the buffer's size).
    LineReader(std::string path, std::size_t maxLineBytes, std::size_t chunk = 1 << 16);
    ~LineReader();
    LineReader(const LineReader&) = delete;
    LineReader& operator=(const LineReader&) = delete;

    // The next line without its '\n' (a last line need not end with one); false at the end of
    // the file. Throws LineReadError.
    bool next(std::string& line);
    bool lastLineEnded() const { return lastLineEnded_; } // the line ended with '\n'
    long lineNumber() const { return lineNumber_; }       // of the last line returned, from 1
    std::uint64_t lineEnd() const { return lineEnd_; }    // bytes up to the last line's end

    bool regular() const { return regular_; }
    bool isOpen() const { return fd_ >= 0; }
    void suspend(); // releases the descriptor of a regular file; next() reopens it

private:
    bool fill(); // reads one chunk into the buffer; false at the end of the file
    bool take(std::string& line, std::size_t length, bool ended); // hands out a line
    void reopen();

    std::string path_;
    std::size_t maxLine_, chunk_;
    int fd_ = -1;
    bool regular_ = false, ended_ = false, lastLineEnded_ = false;
    dev_t device_ = 0;
    ino_t inode_ = 0;
    std::uint64_t readOffset_ = 0, lineEnd_ = 0;
    std::string buffer_;
    std::size_t position_ = 0; // first byte of buffer_ not yet handed out
    long lineNumber_ = 0;
};

} // namespace kinstab
