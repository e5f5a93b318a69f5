// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Triplet shear test data from CSV, one row per sample, in the layout of the transcribed
// Furgerson (1980) Table 1 (resources/data/furgerson1980/table1_triplet_tests.csv):
//   configuration,cp_psi,test_no,delta_in,shear_kips[,any further columns]
// Columns are found by their header names, in any order; extra columns (confidence, note)
// are ignored. Fields may be quoted ("..., ""quoted"" ..."). Blank lines and lines starting
// with '#' are skipped. Rows of one (configuration, cp_psi, test_no) form one curve, in the
// order the curves first appear.

#include "core/friction/TripletCurve.h"

#include <stdexcept>
#include <string>
#include <vector>

namespace kinstab {

// Every problem is reported as "<source> line N, column 'name': what" (or without the column
// when the whole line is at fault), so an engineer can find it in the spreadsheet.
struct TripletCsvError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

std::vector<TripletCurve> parseTripletCsv(const std::string& text, const std::string& sourceName);
std::vector<TripletCurve> readTripletCsv(const std::string& path);

// One CSV record split into fields (RFC 4180 quoting within a line). Throws
// std::invalid_argument on an unterminated quote.
std::vector<std::string> splitCsvLine(const std::string& line);

} // namespace kinstab
