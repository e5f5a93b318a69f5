// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/friction/TripletCsv.h"

#include "core/base/InputLimits.h"
#include "core/base/TextInput.h"

#include <array>
#include <charconv>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <tuple>
#include <utility>

namespace kinstab {
namespace {

const std::array<std::string, 5> kColumns = {"configuration", "cp_psi", "test_no", "delta_in",
                                             "shear_kips"};

struct Where {
    const std::string& source;
    int line;
    std::string at(const std::string& column = {}) const {
        std::string s = source + " line " + std::to_string(line);
        return column.empty() ? s : s + ", column '" + column + "'";
    }
};

double parseNumber(const std::string& field, const Where& where, const std::string& column) {
    double v = 0.0;
    const char* end = field.data() + field.size();
    const auto [ptr, ec] = std::from_chars(field.data(), end, v);
    if (field.empty() || ec != std::errc() || ptr != end || !std::isfinite(v))
        throw TripletCsvError(where.at(column) + ": " + quotedToken(field) + " is not a number");
    return v;
}

// Index of each required column in the header; throws naming the missing one.
std::array<std::size_t, 5> headerIndices(const std::vector<std::string>& header,
                                         const Where& where) {
    std::array<std::size_t, 5> idx{};
    for (std::size_t k = 0; k < kColumns.size(); ++k) {
        std::size_t i = 0;
        while (i < header.size() && trimmed(header[i]) != kColumns[k])
            ++i;
        if (i == header.size())
            throw TripletCsvError(where.at() + ": header has no column '" + kColumns[k] +
                                  "' (needs configuration,cp_psi,test_no,delta_in,shear_kips)");
        idx[k] = i;
    }
    return idx;
}

} // namespace

std::vector<std::string> splitCsvLine(const std::string& line) {
    std::vector<std::string> fields(1);
    bool quoted = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
        const char ch = line[i];
        if (quoted) {
            if (ch == '"' && i + 1 < line.size() && line[i + 1] == '"')
                fields.back() += '"', ++i;
            else if (ch == '"')
                quoted = false;
            else
                fields.back() += ch;
        } else if (ch == '"')
            quoted = true;
        else if (ch == ',')
            fields.emplace_back();
        else if (ch != '\r')
            fields.back() += ch;
    }
    if (quoted) throw std::invalid_argument("unterminated quoted field");
    return fields;
}

namespace {

// One data row: its curve's key (configuration, C_p, test), and one sample of it.
struct TripletRow {
    std::string config, test;
    double cp = 0, delta = 0, shear = 0;
    std::string deltaText; // as written, for the message when it does not increase
};

std::vector<std::string> csvFields(const std::string& line, const Where& where) {
    try {
        return splitCsvLine(line);
    } catch (const std::invalid_argument& e) {
        throw TripletCsvError(where.at() + ": " + e.what());
    }
}

// The row's fields at the header's columns; throws naming the line, column and value.
TripletRow parseRow(const std::vector<std::string>& f, const std::array<std::size_t, 5>& col,
                    const Where& where) {
    for (std::size_t k = 0; k < col.size(); ++k)
        if (col[k] >= f.size())
            throw TripletCsvError(where.at(kColumns[k]) + ": missing (line has " +
                                  std::to_string(f.size()) + " fields)");
    TripletRow r;
    r.config = trimmed(f[col[0]]);
    r.test = trimmed(f[col[2]]);
    if (r.config.empty()) throw TripletCsvError(where.at("configuration") + ": empty");
    if (r.test.empty()) throw TripletCsvError(where.at("test_no") + ": empty");
    r.cp = parseNumber(trimmed(f[col[1]]), where, "cp_psi");
    r.delta = parseNumber(trimmed(f[col[3]]), where, "delta_in");
    r.shear = parseNumber(trimmed(f[col[4]]), where, "shear_kips");
    if (!(r.cp > 0.0))
        throw TripletCsvError(where.at("cp_psi") + ": must be > 0, got " +
                              quotedToken(trimmed(f[col[1]])));
    if (!(r.shear > 0.0))
        throw TripletCsvError(where.at("shear_kips") + ": must be > 0, got " +
                              quotedToken(trimmed(f[col[4]])));
    r.deltaText = trimmed(f[col[3]]);
    return r;
}

// The curves in the order they first appear, and where each is in that list by its key.
struct TripletCurves {
    std::vector<TripletCurve> curves;
    std::map<std::tuple<std::string, double, std::string>, std::size_t> index;

    // The row's sample appended to its curve; throws when delta does not increase along it.
    void add(const TripletRow& row, const Where& where) {
        const auto key = std::make_tuple(row.config, row.cp, row.test);
        auto [it, added] = index.try_emplace(key, curves.size());
        if (added) curves.push_back(TripletCurve{row.config, row.cp, row.test, {}, {}});
        TripletCurve& c = curves[it->second];
        const Eigen::Index n = c.delta.size();
        if (n > 0 && !(row.delta > c.delta(n - 1)))
            throw TripletCsvError(where.at("delta_in") + ": " + row.deltaText +
                                  " does not increase on the previous " + "sample of " +
                                  curveLabel(c));
        c.delta.conservativeResize(n + 1);
        c.shear.conservativeResize(n + 1);
        c.delta(n) = row.delta;
        c.shear(n) = row.shear;
    }
};

} // namespace

std::vector<TripletCurve> parseTripletCsv(const std::string& text, const std::string& source) {
    std::istringstream in{std::string(withoutBom(text))}; // Excel's "CSV UTF-8" starts with a BOM
    std::string line;
    TripletCurves read;
    std::array<std::size_t, 5> col{};
    bool haveHeader = false;
    for (int lineNo = 1; std::getline(in, line); ++lineNo) {
        const Where where{source, lineNo};
        if (trimmed(line).empty() || trimmed(line)[0] == '#') continue;
        const std::vector<std::string> f = csvFields(line, where);
        if (!haveHeader) {
            col = headerIndices(f, where);
            haveHeader = true;
            continue;
        }
        read.add(parseRow(f, col, where), where);
    }
    if (!haveHeader) throw TripletCsvError(source + ": empty file (no header line)");
    if (read.curves.empty()) throw TripletCsvError(source + ": no data rows after the header");
    for (const TripletCurve& c : read.curves)
        if (const std::string e = validateCurve(c); !e.empty())
            throw TripletCsvError(source + ": " + e);
    return std::move(read.curves);
}

std::vector<TripletCurve> readTripletCsv(const std::string& path) {
    const FileText f = readTextFile(path, limits::kMaxCsvFileBytes);
    if (!f.error.empty()) throw TripletCsvError(path + ": " + f.error);
    return parseTripletCsv(f.text, path);
}

} // namespace kinstab
