// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// libFuzzer harnesses (built and run by scripts/fuzz.sh): each feeds the bytes to one reader
// and lets only that reader's documented error through. Anything else — a crash, a sanitizer
// report, another exception escaping — is a finding.

#include <cstddef>
#include <cstdint>
#include <string>

inline std::string fuzzText(const std::uint8_t* data, std::size_t size) {
    return std::string(reinterpret_cast<const char*>(data), size);
}
