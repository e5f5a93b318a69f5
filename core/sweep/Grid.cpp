#include "core/sweep/Grid.h"

#include <charconv>
#include <cmath>
#include <sstream>

namespace kinstab {

namespace {
// std::from_chars, not std::stod: stod follows the C locale, and the GUI sets the user's, in
// which "0.70" may stop at the '.' (de_DE) and a project's grid would not open.
bool parseNumber(const std::string& s, double& out) {
    std::size_t b = s.find_first_not_of(" \t\n");
    if (b == std::string::npos) return false;
    if (s[b] == '+' && b + 1 < s.size() && s[b + 1] != '-') ++b;
    const char* last = s.data() + s.size();
    const auto [end, ec] = std::from_chars(s.data() + b, last, out);
    return ec == std::errc() && end == last && std::isfinite(out);
}
std::string trim(const std::string& s) {
    const auto b = s.find_first_not_of(" \t");
    if (b == std::string::npos) return {};
    const auto e = s.find_last_not_of(" \t");
    return s.substr(b, e - b + 1);
}
} // namespace

std::vector<double> linspaceStep(double start, double stop, double step) {
    std::vector<double> v;
    const double n = (stop - start) / step;
    const long count = static_cast<long>(std::floor(n + 1e-9)) + 1;
    v.reserve(static_cast<std::size_t>(std::max(count, 0L)));
    for (long i = 0; i < count; ++i)
        v.push_back(start + static_cast<double>(i) * step);
    return v;
}

ParsedList parseList(const std::string& text) {
    ParsedList out;
    const std::string t = trim(text);
    if (t.empty()) {
        out.error = "empty list";
        return out;
    }
    if (t.find(':') != std::string::npos) {
        std::vector<std::string> parts;
        std::stringstream ss(t);
        std::string item;
        while (std::getline(ss, item, ':'))
            parts.push_back(trim(item));
        double a = 0, b = 0, h = 0;
        if (parts.size() != 3 || !parseNumber(parts[0], a) || !parseNumber(parts[1], b) ||
            !parseNumber(parts[2], h)) {
            out.error = "'" + t + "' is not start:stop:step";
            return out;
        }
        if (h <= 0.0 || b < a) {
            out.error = "'" + t + "': need step > 0 and stop >= start";
            return out;
        }
        if ((b - a) / h > 1e6) {
            out.error = "'" + t + "': more than a million values";
            return out;
        }
        out.values = linspaceStep(a, b, h);
        return out;
    }
    std::stringstream ss(t);
    std::string item;
    while (std::getline(ss, item, ',')) {
        double x = 0;
        if (!parseNumber(trim(item), x)) {
            out.error = "'" + trim(item) + "' is not a number";
            out.values.clear();
            return out;
        }
        out.values.push_back(x);
    }
    return out;
}

std::string validateGrid(const SweepGrid& g) {
    std::ostringstream s;
    if (g.amplitudes.empty()) return "amplitudes: the grid is empty";
    if (g.frequencies.empty()) return "frequencies: the grid is empty";
    for (double a : g.amplitudes)
        if (!std::isfinite(a) || a < 0.0 || a > 1000.0) {
            s << "amplitudes: " << a << " g is out of range (0 to 1000)";
            return s.str();
        }
    for (double f : g.frequencies)
        if (!std::isfinite(f) || f <= 0.0 || f > 1000.0) {
            s << "frequencies: " << f << " Hz is out of range (> 0, at most 1000)";
            return s.str();
        }
    return {};
}

} // namespace kinstab
