// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Output that never leaves a torn or half-written file behind (POSIX): the one writer of every
// file kinstab writes, whole (writeFileAtomically) or a block at a time (AtomicFileWriter: study
// rows, merges), so that memory need not grow with the output.
//
// The bytes go to a new temporary file in the target's folder, ".NAME.RANDOM.tmp", with an
// unpredictable name created exclusively (O_CREAT|O_EXCL|O_NOFOLLOW, so a file or symlink
// planted at that name is never opened) and locked (flock) while its writer lives. commit()
// fsyncs it, renames it over the target (atomic on one filesystem) and fsyncs the folder. On
// any failure, and on SIGINT/SIGTERM/SIGHUP in kinstab-cli (core/io/SignalCleanup.h), the
// temporary file is removed and the old target is left exactly as it was. A target that exists
// and is not a regular file (/dev/null, a FIFO, a terminal) is written straight through
// instead: renaming over a device node would replace it with a regular file. A target that is
// a symlink keeps its link; the file it points to is replaced.

#include "core/io/SignalCleanup.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace kinstab {

struct FileError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// An output could not be written ("cannot write X: No space left on device"); nothing was
// replaced.
struct WriteError : FileError {
    using FileError::FileError;
};

class AtomicFileWriter {
public:
    // What becomes of the temporary file when its writer ends without a commit (an exception,
    // SIGINT/SIGTERM): removed, or kept for a run that continues from it (study --resume).
    enum class Unfinished { Remove, Keep };

    // Creates the temporary file beside the target. Throws WriteError.
    explicit AtomicFileWriter(const std::string& path, Unfinished unfinished = Unfinished::Remove);
    // Takes over a temporary file that an earlier writer of path left (killed before its
    // commit), locked so that no other run takes it too, and kept when unfinished. Nothing
    // when it is in use by a running writer, is not a regular file of this user's with one
    // link, or cannot be opened.
    static std::unique_ptr<AtomicFileWriter> adopt(const std::string& path,
                                                   const std::string& temporary);
    // The temporary files writers of path left, in name order: "." NAME "." 12 characters
    // ".tmp" in the target's folder (as many as kill -9 left; those in use are included).
    static std::vector<std::string> leftovers(const std::string& path);

    ~AtomicFileWriter(); // removes an uncommitted temporary file unless Unfinished::Keep
    AtomicFileWriter(const AtomicFileWriter&) = delete;
    AtomicFileWriter& operator=(const AtomicFileWriter&) = delete;

    void write(std::string_view bytes); // throws WriteError
    // Keeps the temporary file's first `bytes` bytes and writes on after them. Throws.
    void truncate(std::uint64_t bytes);
    std::uint64_t size() const; // of the temporary file as it is now
    void commit();              // throws WriteError; the target is the new file
    void discard();             // removes the temporary file now, whatever Unfinished says
    const std::string& temporary() const { return temporary_; } // empty: written straight

private:
    AtomicFileWriter() = default;

    std::string path_, target_, temporary_;
    int fd_ = -1;
    bool keep_ = false;
    std::optional<RemovedOnSignal> removal_;
};

void writeFileAtomically(const std::string& path, std::string_view bytes); // throws WriteError
// Writes to standard output and flushes it, so a full or closed stdout is an error, not a
// silent loss.
void writeStandardOutput(std::string_view bytes); // throws WriteError
// Flushes what std::cout and stdio still hold; throws WriteError if any of it was lost.
void flushStandardOutput();
std::string readWholeFile(const std::string& path); // throws FileError

} // namespace kinstab
