// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A number to a few significant digits in the C locale ("0.2019", "1.29e+07"), for messages
// and verdict texts that give a size rather than a value to read back (formatDouble, in
// core/base/TextInput.h, gives the shortest exact text).

#include <locale>
#include <sstream>
#include <string>

namespace kinstab {

inline std::string significantDigits(double x, int digits) {
    std::ostringstream s;
    s.imbue(std::locale::classic());
    s.precision(digits);
    s << x;
    return s.str();
}

} // namespace kinstab
