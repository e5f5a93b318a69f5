// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Whole-file output that never leaves a torn or half-written file behind (POSIX).
//
// writeFileAtomically writes the bytes to a new temporary file in the target's folder, with an
// unpredictable name created exclusively (O_CREAT|O_EXCL|O_NOFOLLOW, so a file or symlink
// planted at that name is never opened), fsyncs it, renames it over the target (atomic on one
// filesystem) and fsyncs the folder. On any failure the temporary file is removed and the old
// target is left exactly as it was. A target that exists and is not a regular file (/dev/null,
// a FIFO, a terminal) is written straight through instead: renaming over a device node would
// replace it with a regular file. A target that is a symlink keeps its link; the file it
// points to is replaced.

#include <stdexcept>
#include <string>
#include <string_view>

namespace kinstab {

struct FileError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// An output could not be written ("cannot write X: No space left on device"); nothing was
// replaced.
struct WriteError : FileError {
    using FileError::FileError;
};

void writeFileAtomically(const std::string& path, std::string_view bytes); // throws WriteError
// Writes to standard output and flushes it, so a full or closed stdout is an error, not a
// silent loss.
void writeStandardOutput(std::string_view bytes); // throws WriteError
// Flushes what std::cout and stdio still hold; throws WriteError if any of it was lost.
void flushStandardOutput();
std::string readWholeFile(const std::string& path); // throws FileError

} // namespace kinstab
