// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A building code as the report and the GUI draw it: its short name and its colour, both from
// core's code catalogue (core/codes/CodeCatalog.h), so a code looks the same everywhere.

#include <QColor>
#include <QString>

#include <string>

namespace kinstab::report {

// "UBC 1976", "ATC 3-06", ... for labels and legends; the key itself when it names no code.
QString shortCodeName(const std::string& key);
// The code's colour; grey for an unknown key.
QColor codeColour(const std::string& key);

} // namespace kinstab::report
