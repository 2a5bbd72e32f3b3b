#include <scene/json_reader.h>

#include <core/text.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace rayrad::scene {

using nlohmann::json;

namespace {
/// `value` as compact JSON (as json::dump writes it), but at most `budget` characters (more means "too long to
/// show"): arrays and objects are written element by element, so a huge or deeply nested
/// value is never serialised whole. Recursion stops with the budget, two characters a
/// level at least.
void writeBounded(const json& value, std::string& out, size_t budget) {
    if (out.size() > budget) return;
    if (value.is_array()) {
        out += '[';
        bool first = true;
        for (const json& v : value) {
            if (out.size() > budget) return;
            if (!first) out += ',';
            first = false;
            writeBounded(v, out, budget);
        }
        out += ']';
    } else if (value.is_object()) {
        out += '{';
        bool first = true;
        for (auto it = value.begin(); it != value.end(); ++it) {
            if (out.size() > budget) return;
            if (!first) out += ',';
            first = false;
            out += json(it.key()).dump(-1, ' ', false, json::error_handler_t::replace) + ':';
            writeBounded(it.value(), out, budget);
        }
        out += '}';
    } else {
        std::string s = value.dump(-1, ' ', false, json::error_handler_t::replace);  // invalid UTF-8 from --set
        out += s.size() > budget + 1 ? s.substr(0, budget + 1) : s;
    }
}
}  // namespace

std::string describe(const json& value) {
    constexpr size_t kShown = 40;
    std::string s;
    writeBounded(value, s, kShown);
    switch (value.type()) {
        case json::value_t::array:
        case json::value_t::object:
            // Short ones in full ("[1280,720.5]"), long ones by their size.
            if (s.size() <= kShown) return s;
            return value.is_array() ? fmt::format("an array of {} values", value.size()) : "an object";
        case json::value_t::null: return "null";
        default: return s.size() > kShown ? s.substr(0, kShown - 3) + "..." : s;
    }
}

size_t tooDeepAt(const std::string& text, int limit) {
    int depth = 0;
    bool inString = false;
    for (size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (inString) {
            if (c == '\\')
                ++i;
            else if (c == '"')
                inString = false;
        } else if (c == '"') {
            inString = true;
        } else if (c == '[' || c == '{') {
            if (++depth > limit) return i;
        } else if (c == ']' || c == '}') {
            --depth;
        }
    }
    return std::string::npos;
}

static size_t editDistance(const std::string& a, const std::string& b) {
    std::vector<size_t> row(b.size() + 1);
    for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (size_t i = 1; i <= a.size(); ++i) {
        size_t diag = row[0];
        row[0] = i;
        for (size_t j = 1; j <= b.size(); ++j) {
            size_t up = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] == b[j - 1] ? 0 : 1)});
            diag = up;
        }
    }
    return row[b.size()];
}

std::string closestMatch(const std::string& word, const std::vector<std::string>& candidates) {
    for (const auto& c : candidates)
        if (toLower(c) == toLower(word)) return c;  // "Materials" → "materials"
    std::string best;
    size_t bestDistance = 4;
    for (const auto& c : candidates) {
        size_t d = editDistance(word, c);
        if (d < bestDistance) {
            bestDistance = d;
            best = c;
        }
    }
    return best;
}

JsonObject::JsonObject(const json& j, std::string path, ParseContext& ctx)
    : m_json(j), m_path(std::move(path)), m_ctx(ctx) {}

bool JsonObject::has(const std::string& key) const { return m_json.contains(key); }

const json* JsonObject::get(const std::string& key) {
    m_read.insert(key);
    auto it = m_json.find(key);
    return it == m_json.end() ? nullptr : &*it;
}

/// True when `word` looks like `key` mistyped: one letter off, two neighbours swapped,
/// or (keys of 6 letters or more) two letters off. Stricter than closestMatch(), because
/// the other keys of the object are not known yet ("max" is not a typo of "min").
static bool likelyTypo(const std::string& word, const std::string& key) {
    if (toLower(word) == toLower(key)) return true;  // "Intensity_CD": keys are case-sensitive
    size_t d = editDistance(word, key);
    if (d <= 1 || (key.size() >= 6 && d <= 2)) return true;
    if (word.size() != key.size()) return false;
    std::vector<size_t> differ;
    for (size_t i = 0; i < key.size(); ++i)
        if (word[i] != key[i]) differ.push_back(i);
    return differ.size() == 2 && differ[1] == differ[0] + 1 && word[differ[0]] == key[differ[1]] &&
           word[differ[1]] == key[differ[0]];
}

void JsonObject::required(const std::string& key) {
    if (has(key)) return;
    // A misspelt required key ("mni" for "min") is named as such, once (finish() then
    // takes it as read).
    for (auto it = m_json.begin(); it != m_json.end(); ++it) {
        const std::string& candidate = it.key();
        if (!m_read.count(candidate) && likelyTypo(candidate, key)) {
            m_read.insert(candidate);
            error(candidate, fmt::format("unknown key (did you mean \"{}\"? it is required)", key));
            return;
        }
    }
    m_ctx.error(m_path.empty() ? "/" : m_path, fmt::format("missing required key \"{}\"", key));
}

static bool isNumber(const json& v) { return v.is_number(); }

std::optional<double> JsonObject::number(const std::string& key) {
    const json* v = get(key);
    if (!v) return std::nullopt;
    if (v->is_string()) {
        // JSON has no NaN/Inf; people write them as strings. Name the problem plainly.
        std::string s = v->get<std::string>();
        const std::string lower = toLower(s);
        if (lower.find("nan") != std::string::npos || lower.find("inf") != std::string::npos) {
            error(key, fmt::format("expected a finite number, got {}", describe(*v)));
            return std::nullopt;
        }
    }
    if (!isNumber(*v)) {
        error(key, fmt::format("expected a number, got {}", describe(*v)));
        return std::nullopt;
    }
    double d = v->get<double>();
    if (!std::isfinite(d)) {
        error(key, fmt::format("expected a finite number, got {}", describe(*v)));
        return std::nullopt;
    }
    return d;
}

double JsonObject::positive(const std::string& key, double fallback) {
    auto v = number(key);
    if (!v) return fallback;
    if (*v <= 0) {
        error(key, fmt::format("expected a positive number, got {}", describe(m_json.at(key))));
        return fallback;
    }
    return *v;
}

double JsonObject::nonNegative(const std::string& key, double fallback) {
    auto v = number(key);
    if (!v) return fallback;
    if (*v < 0) {
        error(key, fmt::format("expected a number >= 0, got {}", describe(m_json.at(key))));
        return fallback;
    }
    return *v;
}

int JsonObject::integer(const std::string& key, int fallback, int minValue, int maxValue) {
    const json* v = get(key);
    if (!v) return fallback;
    if (!v->is_number_integer() && !(v->is_number_float() && std::floor(v->get<double>()) == v->get<double>())) {
        error(key, fmt::format("expected a whole number, got {}", describe(*v)));
        return fallback;
    }
    double d = v->get<double>();
    if (d < minValue || d > maxValue) {
        error(key, fmt::format("expected a whole number from {} to {}, got {}", minValue, maxValue, describe(*v)));
        return fallback;
    }
    return static_cast<int>(d);
}

std::optional<std::string> JsonObject::string(const std::string& key) {
    const json* v = get(key);
    if (!v) return std::nullopt;
    if (!v->is_string()) {
        error(key, fmt::format("expected a string, got {}", describe(*v)));
        return std::nullopt;
    }
    std::string text = v->get<std::string>();
    // A NUL ("\u0000") would cut a file name or a name short where the system reads it.
    if (text.find('\0') != std::string::npos) {
        error(key, "the string holds a NUL character (\\u0000)");
        return std::nullopt;
    }
    return text;
}

std::optional<bool> JsonObject::boolean(const std::string& key) {
    const json* v = get(key);
    if (!v) return std::nullopt;
    if (!v->is_boolean()) {
        error(key, fmt::format("expected true or false, got {}", describe(*v)));
        return std::nullopt;
    }
    return v->get<bool>();
}

static std::optional<Vec3> toVec3(const json& v) {
    if (!v.is_array() || v.size() != 3) return std::nullopt;
    Vec3 r;
    for (int i = 0; i < 3; ++i) {
        if (!v[i].is_number()) return std::nullopt;
        r[i] = v[i].get<double>();
        if (!std::isfinite(r[i])) return std::nullopt;
    }
    return r;
}

std::optional<Vec3> JsonObject::vec3(const std::string& key) {
    const json* v = get(key);
    if (!v) return std::nullopt;
    auto r = toVec3(*v);
    if (!r) {
        error(key, fmt::format("expected three finite numbers [x, y, z], got {}", describe(*v)));
    } else if (maxAbs(*r) > kMaxCoordinate) {
        error(key, fmt::format("expected numbers within ±1e9 (m), got {}", describe(*v)));
        return std::nullopt;
    }
    return r;
}

std::optional<Rgb> JsonObject::rgb(const std::string& key, double lo, double hi, bool hiInclusive) {
    const json* v = get(key);
    if (!v) return std::nullopt;
    Rgb c;
    if (v->is_number()) {
        c = Rgb(v->get<double>());
    } else if (auto r = toVec3(*v)) {
        c = *r;
    } else {
        error(key, fmt::format("expected a number or [r, g, b], got {}", describe(*v)));
        return std::nullopt;
    }
    for (int i = 0; i < 3; ++i) {
        bool ok = std::isfinite(c[i]) && c[i] >= lo && (hiInclusive ? c[i] <= hi : c[i] < hi);
        if (!ok) {
            error(key, fmt::format("expected values in [{}, {}{}, got {}", lo, hi, hiInclusive ? "]" : ")",
                                   describe(*v)));
            return std::nullopt;
        }
    }
    return c;
}

std::vector<Vec3> JsonObject::points(const std::string& key) {
    const json* v = get(key);
    std::vector<Vec3> out;
    if (!v) return out;
    if (!v->is_array()) {
        error(key, fmt::format("expected a list of [x, y, z] points, got {}", describe(*v)));
        return out;
    }
    for (size_t i = 0; i < v->size(); ++i) {
        auto p = toVec3((*v)[i]);
        if (!p) {
            m_ctx.error(childPath(key) + "/" + std::to_string(i),
                        fmt::format("expected three finite numbers [x, y, z], got {}", describe((*v)[i])));
            return {};
        }
        out.push_back(*p);
    }
    return out;
}

std::optional<JsonObject> JsonObject::object(const std::string& key) {
    const json* v = get(key);
    if (!v) return std::nullopt;
    if (!v->is_object()) {
        error(key, fmt::format("expected an object, got {}", describe(*v)));
        return std::nullopt;
    }
    return JsonObject(*v, childPath(key), m_ctx);
}

const json* JsonObject::array(const std::string& key) {
    const json* v = get(key);
    if (!v) return nullptr;
    if (!v->is_array()) {
        error(key, fmt::format("expected an array, got {}", describe(*v)));
        return nullptr;
    }
    return v;
}

void JsonObject::finish(const std::set<std::string>& alsoAllowed) {
    std::vector<std::string> known(m_read.begin(), m_read.end());
    known.insert(known.end(), alsoAllowed.begin(), alsoAllowed.end());
    for (auto it = m_json.begin(); it != m_json.end(); ++it) {
        if (m_read.count(it.key()) || alsoAllowed.count(it.key())) continue;
        std::string hint = closestMatch(it.key(), known);
        error(it.key(), hint.empty() ? "unknown key" : fmt::format("unknown key (did you mean \"{}\"?)", hint));
    }
}

std::string findDuplicateKey(const std::string& text) {
    // A small scanner over text nlohmann::json has already accepted: it follows strings,
    // objects and arrays only, and remembers where each key of each open object began.
    struct Frame {
        bool object = false;
        bool expectKey = false;
        std::map<std::string, size_t> keys;  // key → byte offset of its opening quote
    };
    std::vector<Frame> stack;
    auto lineColumn = [&](size_t byte) {
        size_t line = 1, column = 1;
        for (size_t i = 0; i < byte; ++i) text[i] == '\n' ? (++line, column = 1) : ++column;
        return fmt::format("line {}, column {}", line, column);
    };
    for (size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (c == '{' || c == '[') {
            stack.push_back({c == '{', c == '{', {}});
        } else if ((c == '}' || c == ']') && !stack.empty()) {
            stack.pop_back();
        } else if (c == ',' && !stack.empty() && stack.back().object) {
            stack.back().expectKey = true;
        } else if (c == '"') {
            const size_t start = i;
            std::string raw;
            for (++i; i < text.size() && text[i] != '"'; ++i) {
                if (text[i] == '\\' && i + 1 < text.size()) raw += text[i++];
                raw += text[i];
            }
            if (!stack.empty() && stack.back().expectKey) {
                stack.back().expectKey = false;
                auto [at, fresh] = stack.back().keys.emplace(raw, start);
                if (!fresh)
                    return fmt::format("{}: the key \"{}\" appears twice in one object (first at {}); "
                                       "JSON keeps only the last, so remove one",
                                       lineColumn(start), raw, lineColumn(at->second));
            }
        }
    }
    return "";
}

}  // namespace rayrad::scene
