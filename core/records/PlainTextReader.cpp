// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/records/PlainTextReader.h"

#include "core/base/InputLimits.h"
#include "core/base/TextInput.h"

#include <cmath>

namespace kinstab {

namespace {

bool isComment(const std::string& line) {
    const std::size_t a = line.find_first_not_of(" \t");
    return a != std::string::npos && (line[a] == '#' || line[a] == '%');
}

std::vector<std::string_view> splitFields(const std::string& line) {
    std::string_view v(line);
    std::vector<std::string_view> out;
    std::size_t i = 0;
    while (i <= v.size()) {
        while (i < v.size() && (v[i] == ' ' || v[i] == '\t'))
            ++i;
        if (i >= v.size()) break;
        std::size_t j = i;
        while (j < v.size() && v[j] != ' ' && v[j] != '\t' && v[j] != ',' && v[j] != ';')
            ++j;
        out.push_back(v.substr(i, j - i));
        while (j < v.size() && (v[j] == ' ' || v[j] == '\t'))
            ++j;
        if (j < v.size() && (v[j] == ',' || v[j] == ';')) ++j;
        i = j;
    }
    return out;
}

void checkCount(const RecordText& text, std::size_t i, std::size_t count) {
    if (count >= limits::kMaxRecordSamples)
        text.fail(i, "more than the limit of " + std::to_string(limits::kMaxRecordSamples) +
                         " samples");
}

Accelerogram plain(const RecordText& text, const char* format, double dt, AccelUnit unit) {
    Accelerogram a;
    a.sourceFile = text.source();
    a.format = format;
    a.dt = dt;
    a.fileUnit = unit;
    return a;
}

} // namespace

Accelerogram parseValues(const RecordText& text, double dt, AccelUnit unit) {
    if (!(dt > 0.0) || !std::isfinite(dt))
        text.failFile("dt " + formatDouble(dt) + " s: must be > 0");
    Accelerogram a = plain(text, "values", dt, unit);
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (isComment(text.line(i))) continue;
        for (std::string_view token : splitWhitespace(text.line(i))) {
            checkCount(text, i, a.samples.size());
            a.samples.push_back(
                finiteAt(text, i, token, "value " + std::to_string(a.samples.size() + 1)) *
                gPerUnit(unit));
        }
    }
    if (a.samples.size() < 2)
        text.fail(text.size() == 0 ? 0 : text.size() - 1, "found " +
                                                              std::to_string(a.samples.size()) +
                                                              " values: a record needs at least 2");
    return a;
}

Accelerogram parseTimeAccel(const RecordText& text, AccelUnit unit) {
    Accelerogram a = plain(text, "time-accel", 0.0, unit);
    std::vector<double> time;
    std::vector<std::size_t> lineOf;
    bool sawRow = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text.blank(i) || isComment(text.line(i))) continue;
        const auto fields = splitFields(text.line(i));
        if (!sawRow && !parseNumber(fields.front())) { // a first line of column names
            sawRow = true;
            continue;
        }
        sawRow = true;
        checkCount(text, i, time.size());
        if (fields.size() == 1)
            text.fail(i, "one value on the line: a single-column record needs dt");
        if (fields.size() != 2)
            text.fail(i, "expected 2 columns (time, accel), found " +
                             std::to_string(fields.size()) + " (a file of values only needs dt)");
        time.push_back(finiteAt(text, i, fields[0], "time"));
        a.samples.push_back(finiteAt(text, i, fields[1], "acceleration") * gPerUnit(unit));
        lineOf.push_back(i);
    }
    if (time.size() < 2)
        text.fail(text.size() == 0 ? 0 : text.size() - 1,
                  "found " + std::to_string(time.size()) + " rows: a record needs at least 2");
    const double firstStep = time[1] - time[0];
    for (std::size_t k = 1; k < time.size(); ++k) {
        const double step = time[k] - time[k - 1];
        if (step <= 0.0)
            text.fail(lineOf[k], "time " + formatDouble(time[k]) + " does not increase");
        if (std::abs(step - firstStep) > 1e-3 * firstStep)
            text.fail(lineOf[k], "time step " + formatDouble(step) + " s differs from the first, " +
                                     formatDouble(firstStep) +
                                     " s: samples must be equally spaced");
    }
    a.dt = (time.back() - time.front()) /
           static_cast<double>(time.size() - 1); // mean: rounding averages out
    return a;
}

} // namespace kinstab
