// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Test access to the shipped Furgerson (1980) transcriptions
// (resources/data/furgerson1980/, see PROVENANCE.md there).

#include "core/friction/TripletCsv.h"

#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace furgerson {

inline std::string dataPath(const std::string& file) {
    return std::string(KINSTAB_SOURCE_DIR) + "/resources/data/furgerson1980/" + file;
}

inline std::vector<kinstab::TripletCurve> table1() {
    return kinstab::readTripletCsv(dataPath("table1_triplet_tests.csv"));
}

// Rows of a CSV table as header -> field maps.
inline std::vector<std::map<std::string, std::string>> rows(const std::string& file) {
    std::ifstream in(dataPath(file));
    if (!in) throw std::runtime_error("cannot open " + dataPath(file));
    std::string line;
    std::getline(in, line);
    const std::vector<std::string> header = kinstab::splitCsvLine(line);
    std::vector<std::map<std::string, std::string>> out;
    while (std::getline(in, line)) {
        if (line.empty()) continue;
        const std::vector<std::string> f = kinstab::splitCsvLine(line);
        std::map<std::string, std::string> row;
        for (std::size_t i = 0; i < header.size() && i < f.size(); ++i)
            row[header[i]] = f[i];
        out.push_back(row);
    }
    return out;
}

// The run of BJ-F-NG-200 with this test number, from Table 1.
inline kinstab::TripletCurve ng200Run(const std::string& test) {
    for (const kinstab::TripletCurve& c : table1())
        if (c.configuration == "BJ-F-NG" && c.cpPsi == 200 && c.test == test) return c;
    throw std::runtime_error("no BJ-F-NG-200 run " + test);
}

} // namespace furgerson
