// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Output written a block at a time (study rows, merges), so that memory does not grow with its
// size: to standard output for "-", else through core's atomic writer (core/io/AtomicFile.h),
// so the file appears whole at commit() or not at all.

#include "core/io/AtomicFile.h"

#include <memory>
#include <string>
#include <string_view>

namespace kinstab::cli {

class StreamedOutput {
public:
    explicit StreamedOutput(const std::string& path); // throws WriteError
    // study --resume: writes on after the complete rows of an adopted temporary file.
    explicit StreamedOutput(std::unique_ptr<AtomicFileWriter> resumed);

    void write(std::string_view bytes); // throws WriteError
    void commit();                      // throws WriteError

private:
    std::unique_ptr<AtomicFileWriter> file_; // none: standard output
};

} // namespace kinstab::cli
