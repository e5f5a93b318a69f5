// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A recorded acceleration time series (docs/theory.md §7): equally spaced samples, in g, with the
// metadata of the file it came from. Every reader in core/io returns one of these.

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace kinstab {

// Units an accelerogram file may use. Conversion to g uses standard gravity 9.80665 m/s².
enum class AccelUnit { G, MetresPerS2, CmPerS2, FtPerS2, InPerS2 };
std::string accelUnitName(AccelUnit u); // "g", "m/s2", "cm/s2", "ft/s2", "in/s2"
// Accepts the names above and common spellings ("gal", "cm/sec2", "m/s^2", ...).
std::optional<AccelUnit> accelUnitFromName(const std::string& name);
double gPerUnit(AccelUnit u); // multiply a value in u by this to get g

struct SignedPeak {
    double value = 0; // signed sample with the largest |a|
    double time = 0;  // s, from the first sample
    std::size_t index = 0;
};

struct Accelerogram {
    double dt = 0;               // s, sample spacing
    std::vector<double> samples; // g
    std::string name;            // event / title line of the file
    std::string station;
    std::string component; // e.g. "164", "UP", "CHAN 10: UP"
    std::string sourceFile;
    std::string format;                // e.g. "PEER AT2"
    AccelUnit fileUnit = AccelUnit::G; // units of the values in the file
    std::optional<double> headerPeak;  // the peak the file's header states, in g, when it does

    std::size_t size() const { return samples.size(); }
    double duration() const; // s, from the first to the last sample
    SignedPeak peak() const; // the first sample of largest |a|
};

// A file that cannot be read as an accelerogram. what() is "FILE:LINE: message" (line 0 when
// the problem is not on one line).
class RecordError : public std::runtime_error {
public:
    RecordError(const std::string& file, int line, const std::string& message);
    const std::string& file() const { return file_; }
    int line() const { return line_; }
    const std::string& message() const { return message_; }

private:
    std::string file_;
    int line_;
    std::string message_;
};

// Checks dt > 0, at least two samples, every sample finite; throws RecordError otherwise.
void validateAccelerogram(const Accelerogram& a);

} // namespace kinstab
