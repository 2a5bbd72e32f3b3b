// A thin reader over nlohmann::json that knows its JSON pointer and reports typed errors.
#pragma once

#include <core/math.h>
#include <scene/scene_parser.h>

#include <nlohmann/json.hpp>

#include <optional>
#include <set>
#include <string>
#include <vector>

namespace rayrad::scene {

/// Shared state of one parse: where errors go, and whether any happened.
struct ParseContext {
    ErrorHandler onError;
    int errors = 0;
    void error(const std::string& place, const std::string& message) {
        ++errors;
        onError(place, message);
    }
};

/// One JSON object being read. Every key read is remembered; `finish()` reports the
/// keys nobody asked for, with a "did you mean" suggestion.
class JsonObject {
  public:
    JsonObject(const nlohmann::json& json, std::string path, ParseContext& ctx);

    const std::string& path() const { return m_path; }
    bool has(const std::string& key) const;
    /// The value at `key` without reading it (nullptr when absent): for keys of more than
    /// one form.
    const nlohmann::json* peek(const std::string& key) const {
        auto it = m_json.find(key);
        return it == m_json.end() ? nullptr : &*it;
    }
    std::string childPath(const std::string& key) const { return m_path + "/" + key; }

    /// A finite number; reports and returns `fallback` on a wrong type.
    std::optional<double> number(const std::string& key);
    double number(const std::string& key, double fallback) { return number(key).value_or(fallback); }
    double positive(const std::string& key, double fallback);
    double nonNegative(const std::string& key, double fallback);
    int integer(const std::string& key, int fallback, int minValue, int maxValue);
    std::optional<std::string> string(const std::string& key);
    std::optional<bool> boolean(const std::string& key);
    /// Three finite numbers within ±kMaxCoordinate: a point, an extent or a direction.
    std::optional<Vec3> vec3(const std::string& key);
    /// A grey value or an [r, g, b] triple, each component in [lo, hi) (or [lo, hi]).
    std::optional<Rgb> rgb(const std::string& key, double lo, double hi, bool hiInclusive);
    /// A list of points [[x,y,z], ...].
    std::vector<Vec3> points(const std::string& key);
    /// A nested object (reports if present but not an object).
    std::optional<JsonObject> object(const std::string& key);
    /// A nested array (reports if present but not an array).
    const nlohmann::json* array(const std::string& key);

    void required(const std::string& key);
    void finish(const std::set<std::string>& alsoAllowed = {});

    void error(const std::string& key, const std::string& message) { m_ctx.error(childPath(key), message); }
    ParseContext& context() { return m_ctx; }

  private:
    const nlohmann::json* get(const std::string& key);

    const nlohmann::json& m_json;
    std::string m_path;
    ParseContext& m_ctx;
    std::set<std::string> m_read;
};

/// Short description of a JSON value for messages: `-5`, `"abc"`, `an array`.
std::string describe(const nlohmann::json& value);

/// The closest of `candidates` to `word`: one that differs only in case, else the
/// nearest by edit distance (≤ 3), or "".
std::string closestMatch(const std::string& word, const std::vector<std::string>& candidates);

/// The largest coordinate (m) a scene file's [x, y, z] may hold: a million kilometres. The
/// ray tracer works in single precision, in which a camera at 1e20 m or a light at 1e300 m
/// is no longer a point it can trace from; georeferenced models (UTM, 1e7 m) fit.
constexpr double kMaxCoordinate = 1e9;

/// How deep arrays and objects may nest in a scene file or a --set value: a scene needs
/// about six levels. Deeper text is refused before it is parsed, so nothing that walks
/// a value recursively (copying, printing) meets thousands of levels.
constexpr int kMaxJsonDepth = 64;

/// The byte offset in `text` (JSON, possibly malformed) where arrays and objects first
/// nest deeper than `limit`, skipping strings; npos if they never do.
size_t tooDeepAt(const std::string& text, int limit = kMaxJsonDepth);

/// For JSON text that parses: "line L, column C: the key "k" appears twice in one
/// object (first at line L', column C') ..." for the first duplicate key, or "".
std::string findDuplicateKey(const std::string& text);

}  // namespace rayrad::scene
