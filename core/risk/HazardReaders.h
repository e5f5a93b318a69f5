// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The three hazard readers behind core/risk/HazardFile.h, one per format (OpenQuakeHazard.cpp,
// UsgsHazard.cpp, CsvHazard.cpp), and what they share. text: the whole file without its BOM.

#include "core/risk/HazardFile.h"

#include <string>
#include <string_view>

namespace kinstab {

HazardCurve parseOpenQuakeHazard(std::string_view text, const std::string& label,
                                 const HazardRequest& request);
HazardCurve parseUsgsHazard(const std::string& text, const std::string& label,
                            const HazardRequest& request);
HazardCurve parseCsvHazard(std::string_view text, const std::string& label,
                           const HazardRequest& request);

// The lines of a text one at a time, numbered from 1, without their line ends ("\n", "\r\n").
class TextLines {
public:
    explicit TextLines(std::string_view text) : text_(text) {}
    bool next(std::string_view& line); // false after the last line
    std::size_t number() const { return number_; }

private:
    std::string_view text_;
    std::size_t pos_ = 0, number_ = 0;
};

// "FILE:LINE".
std::string hazardLine(const std::string& label, std::size_t line);
// A finite-or-not number from a CSV field (spaces around it allowed), or a HazardError naming
// where, the column and the text.
double hazardNumber(std::string_view field, const std::string& where, const std::string& column);
// Refuses a curve whose stated measure is not the requested one: "where: the hazard curve's
// intensity measure PGA is not the fragility's SA(1 s)". An unstated measure passes.
void checkHazardMeasure(const HazardMeasure& stated, const HazardRequest& request,
                        const std::string& where);

} // namespace kinstab
