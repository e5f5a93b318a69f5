// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/io/JsonReader.h"

#include "core/base/InputLimits.h"
#include "core/base/TextInput.h"
#include "core/sweep/Grid.h"

#include <algorithm>
#include <cmath>

namespace kinstab {

namespace {
// A value for a message: never the whole of a big array or object (dumping a deeply nested
// one would recurse once per level).
std::string shown(const nlohmann::json& v) {
    if (v.is_array()) return "an array of " + std::to_string(v.size()) + " entries";
    if (v.is_object()) return "an object";
    if (v.is_string()) return nlohmann::json(elided(v.get<std::string>(), 57)).dump();
    return v.dump();
}
} // namespace

int jsonNestingDepth(std::string_view text, int limit) {
    int depth = 0, deepest = 0;
    bool inString = false;
    for (std::size_t i = 0; i < text.size() && deepest <= limit; ++i) {
        const char c = text[i];
        if (inString) {
            if (c == '\\')
                ++i; // the escaped character cannot end the string
            else if (c == '"')
                inString = false;
        } else if (c == '"') {
            inString = true;
        } else if (c == '[' || c == '{') {
            deepest = std::max(deepest, ++depth);
        } else if (c == ']' || c == '}') {
            --depth;
        }
    }
    return deepest;
}

nlohmann::json parseJsonDocument(const std::string& text, std::uintmax_t maxBytes) {
    if (text.size() > maxBytes)
        throw JsonFieldError("document: " + std::to_string(text.size()) +
                             " bytes, more than the limit of " + std::to_string(maxBytes));
    const std::string_view body = withoutBom(text);
    if (jsonNestingDepth(body, limits::kMaxJsonDepth) > limits::kMaxJsonDepth)
        throw JsonFieldError("document: arrays and objects nested more than " +
                             std::to_string(limits::kMaxJsonDepth) + " levels deep");
    try {
        return nlohmann::json::parse(body.begin(), body.end());
    } catch (const nlohmann::json::parse_error& e) {
        // e.byte says where a truncated or corrupt file stops making sense.
        throw JsonFieldError("not valid JSON (truncated or corrupt?) at byte " +
                             std::to_string(e.byte) + ": " + elided(e.what(), 300));
    } catch (const nlohmann::json::exception& e) { // e.g. a number beyond the range of double
        throw JsonFieldError("not valid JSON: " + elided(e.what(), 300));
    }
}

JsonReader::JsonReader(const nlohmann::json& j, std::string path) : j_(&j), path_(std::move(path)) {
    if (!j.is_object())
        throw JsonFieldError((path_.empty() ? "document" : path_) + ": expected an object, got " +
                             shown(j));
}

bool JsonReader::has(const std::string& key) const {
    const auto it = j_->find(key);
    return it != j_->end() && !it->is_null();
}

std::string JsonReader::field(const std::string& key) const {
    return path_.empty() ? key : path_ + "." + key;
}

void JsonReader::fail(const std::string& key, const std::string& message) const {
    throw JsonFieldError(field(key) + ": " + message);
}

const nlohmann::json& JsonReader::raw(const std::string& key) const {
    if (!has(key)) fail(key, "missing");
    return j_->at(key);
}

std::optional<double> JsonReader::optionalNumber(const std::string& key) const {
    if (!has(key)) return std::nullopt;
    const nlohmann::json& v = j_->at(key);
    if (!v.is_number()) fail(key, "expected a number, got " + shown(v));
    const double x = v.get<double>();
    if (!std::isfinite(x)) fail(key, "expected a finite number, got " + shown(v));
    return x;
}

double JsonReader::number(const std::string& key, double fallback) const {
    return optionalNumber(key).value_or(fallback);
}

std::optional<double> JsonReader::optionalInput(const NumberInput& in,
                                                const std::string& key) const {
    const std::string k = key.empty() ? std::string(in.key) : key;
    const std::optional<double> x = optionalNumber(k);
    if (x)
        if (const InputProblem p = checkInput(in, *x); !p.empty()) fail(k, valueAndWhy(p));
    return x;
}

double JsonReader::input(const NumberInput& in, const std::string& key) const {
    return optionalInput(in, key).value_or(in.fallback);
}

double JsonReader::requiredNumber(const std::string& key) const {
    const auto v = optionalNumber(key);
    if (!v) fail(key, "missing (a number is required)");
    return *v;
}

std::optional<int> JsonReader::optionalInteger(const std::string& key) const {
    const auto v = optionalNumber(key);
    if (!v) return std::nullopt;
    if (*v != std::floor(*v) || std::abs(*v) > 1e9)
        fail(key, "expected a whole number, got " + shown(j_->at(key)));
    return static_cast<int>(*v);
}

int JsonReader::integer(const std::string& key, int fallback) const {
    return optionalInteger(key).value_or(fallback);
}

std::optional<std::string> JsonReader::optionalText(const std::string& key) const {
    if (!has(key)) return std::nullopt;
    const nlohmann::json& v = j_->at(key);
    if (!v.is_string()) fail(key, "expected a string, got " + shown(v));
    return v.get<std::string>();
}

std::string JsonReader::text(const std::string& key, const std::string& fallback) const {
    return optionalText(key).value_or(fallback);
}

std::string JsonReader::pathText(const std::string& key, const std::string& fallback) const {
    std::string t = text(key, fallback);
    if (t.find('\0') != std::string::npos) fail(key, "the path contains a NUL character");
    return t;
}

bool JsonReader::boolean(const std::string& key, bool fallback) const {
    if (!has(key)) return fallback;
    const nlohmann::json& v = j_->at(key);
    if (!v.is_boolean()) fail(key, "expected true or false, got " + shown(v));
    return v.get<bool>();
}

std::vector<double> JsonReader::numbers(const std::string& key) const {
    const nlohmann::json& v = raw(key);
    if (v.is_string()) {
        const ParsedList p = parseList(v.get<std::string>());
        if (!p.error.empty()) fail(key, p.error);
        return p.values;
    }
    if (!v.is_array()) fail(key, "expected an array of numbers or a LIST string, got " + shown(v));
    std::vector<double> out;
    for (std::size_t i = 0; i < v.size(); ++i) {
        if (!v[i].is_number() || !std::isfinite(v[i].get<double>()))
            fail(key, "entry " + std::to_string(i) + " is not a finite number: " + shown(v[i]));
        out.push_back(v[i].get<double>());
    }
    return out;
}

std::optional<JsonReader> JsonReader::optionalObject(const std::string& key) const {
    if (!has(key)) return std::nullopt;
    return JsonReader(j_->at(key), field(key));
}

JsonReader JsonReader::object(const std::string& key) const {
    return JsonReader(raw(key), field(key));
}

} // namespace kinstab
