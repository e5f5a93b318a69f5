// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli/StreamedOutput.h"

namespace kinstab::cli {

StreamedOutput::StreamedOutput(const std::string& path) {
    if (!path.empty() && path != "-") file_ = std::make_unique<AtomicFileWriter>(path);
}

StreamedOutput::StreamedOutput(std::unique_ptr<AtomicFileWriter> resumed)
    : file_(std::move(resumed)) {}

void StreamedOutput::write(std::string_view bytes) {
    if (file_)
        file_->write(bytes);
    else
        writeStandardOutput(bytes);
}

void StreamedOutput::commit() {
    if (file_) file_->commit();
}

} // namespace kinstab::cli
