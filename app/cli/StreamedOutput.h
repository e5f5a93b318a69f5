// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Output that is written a block at a time (study rows), so that memory does not grow with its
// size, yet still appears whole or not at all: the blocks go to a temporary file beside the
// target, which is renamed over it only when the last block is in (as core/io/AtomicFile.h does
// for whole texts). "-" or no file: standard output, block by block.

#include <string>
#include <string_view>

namespace kinstab::cli {

class StreamedOutput {
public:
    explicit StreamedOutput(const std::string& path); // throws WriteError
    ~StreamedOutput();                                // removes an uncommitted temporary file
    StreamedOutput(const StreamedOutput&) = delete;
    StreamedOutput& operator=(const StreamedOutput&) = delete;

    void write(std::string_view bytes); // throws WriteError
    void commit();                      // fsync and rename into place; throws WriteError

private:
    std::string path_, temp_;
    int fd_ = -1;
    unsigned mode_ = 0644; // of the finished file
};

} // namespace kinstab::cli
