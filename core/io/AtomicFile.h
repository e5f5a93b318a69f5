#pragma once
// Writes a whole file or nothing: the text goes to a temporary file in the same directory,
// which is then renamed over the target (rename is atomic on one filesystem), so a crash or a
// full disk never leaves a half-written project behind.

#include <stdexcept>
#include <string>

namespace kinstab {

struct FileError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

void writeFileAtomically(const std::string& path, const std::string& text); // throws FileError
std::string readWholeFile(const std::string& path);                         // throws FileError

} // namespace kinstab
