// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// SHA-256 (FIPS 180-4) of bytes, as lowercase hex: the identity of a study's records and
// parameters (core/study/StudyFingerprint.h). Written here because core links no crypto library
// and Qt's QCryptographicHash is not available below app/.

#include <array>
#include <cstdint>
#include <string>
#include <string_view>

namespace kinstab {

class Sha256 {
public:
    Sha256();
    void add(std::string_view bytes);
    std::string hex(); // the digest as 64 lowercase hex digits; ends the hash

private:
    void block(const unsigned char* p);
    std::array<std::uint32_t, 8> h_;
    std::array<unsigned char, 64> pending_{};
    std::size_t pendingSize_ = 0;
    std::uint64_t totalBytes_ = 0;
};

std::string sha256Hex(std::string_view bytes);

} // namespace kinstab
