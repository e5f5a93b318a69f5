// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What the report library throws for a request it cannot print: an unknown section key, a study
// whose files do not match, a folder that does not exist. The message names the field and value;
// the CLI exits 2 on it, the GUI shows it, Python raises ValueError.

#include <stdexcept>

namespace kinstab::report {

struct ReportError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

} // namespace kinstab::report
