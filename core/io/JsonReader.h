// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Typed, path-aware access to a JSON object read from a file: every problem is a
// JsonFieldError naming the field by its path ("building.height: expected a number, got
// \"abc\""). Absent and null keys are the same thing.

#include "core/base/NumberInput.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace kinstab {

struct JsonFieldError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Parses a whole JSON document (a UTF-8 byte-order mark is skipped). Refuses, with a
// JsonFieldError saying where, text that is not JSON, a document larger than maxBytes, nesting
// deeper than limits::kMaxJsonDepth (checked by a scan before parsing, so no recursive walk of
// the document can run out of stack) and numbers beyond the range of double ("1e999").
nlohmann::json parseJsonDocument(const std::string& text, std::uintmax_t maxBytes);
// Deepest nesting of arrays and objects in JSON text (strings are skipped); stops counting
// at limit + 1.
int jsonNestingDepth(std::string_view text, int limit);

class JsonReader {
public:
    // j must be an object (else JsonFieldError naming path).
    JsonReader(const nlohmann::json& j, std::string path);

    bool has(const std::string& key) const;
    std::string field(const std::string& key) const; // "path.key"

    std::optional<double> optionalNumber(const std::string& key) const;
    double number(const std::string& key, double fallback) const;
    double requiredNumber(const std::string& key) const;
    std::optional<int> optionalInteger(const std::string& key) const;
    int integer(const std::string& key, int fallback) const;
    std::optional<std::string> optionalText(const std::string& key) const;
    std::string text(const std::string& key, const std::string& fallback) const;
    // A file's path: text without a NUL character, which would cut the path short when it is
    // handed to the system (another file than the one named would be read).
    std::string pathText(const std::string& key, const std::string& fallback) const;
    bool boolean(const std::string& key, bool fallback) const;
    // An array of numbers, or a LIST string ("0.7:1.15:0.05" or "1,2,3").
    std::vector<double> numbers(const std::string& key) const;
    std::optional<JsonReader> optionalObject(const std::string& key) const;
    JsonReader object(const std::string& key) const;
    const nlohmann::json& raw(const std::string& key) const;
    // A declared input (core/base/NumberInput.h) under its key, or under key when the file
    // names it otherwise: its default when absent, else a number in its range.
    double input(const NumberInput& in, const std::string& key = {}) const;
    std::optional<double> optionalInput(const NumberInput& in, const std::string& key = {}) const;

    [[noreturn]] void fail(const std::string& key, const std::string& message) const;

private:
    const nlohmann::json* j_;
    std::string path_;
};

} // namespace kinstab
