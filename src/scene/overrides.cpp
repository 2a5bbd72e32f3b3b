#include <scene/overrides.h>

#include <core/input_error.h>
#include <scene/json_reader.h>

#include <fmt/format.h>

#include <algorithm>
#include <sstream>

namespace rayrad::scene {

using nlohmann::json;

void applyOverride(json& root, const Override& o, ParseContext& ctx) {
    json* node = &root;
    std::stringstream parts(o.path);
    std::string part;
    std::vector<std::string> keys;
    while (std::getline(parts, part, '.')) keys.push_back(part);
    for (size_t i = 0; i < keys.size(); ++i) {
        const std::string& k = keys[i];
        bool last = i + 1 == keys.size();
        if (node->is_array()) {
            size_t index = 0;
            try {
                if (k.empty() || k.find_first_not_of("0123456789") != std::string::npos) throw std::invalid_argument(k);
                index = std::stoul(k);
            } catch (...) {
                ctx.error("--set " + o.path, fmt::format("\"{}\" is not an array index", k));
                return;
            }
            if (index >= node->size()) {
                ctx.error("--set " + o.path, fmt::format("index {} is out of range (size {})", index, node->size()));
                return;
            }
            node = &(*node)[index];
        } else {
            if (!node->is_object()) *node = json::object();
            if (!last && !node->contains(k)) (*node)[k] = json::object();
            node = &(*node)[k];
        }
    }
    if (tooDeepAt(o.value) != std::string::npos) {
        ctx.error("--set " + o.path, fmt::format("the value nests arrays and objects more than {} levels deep",
                                                 kMaxJsonDepth));
        return;
    }
    json value = json::parse(o.value, nullptr, /*allow_exceptions=*/false);
    *node = value.is_discarded() ? json(o.value) : value;
}

std::string sourceOf(const std::string& place, const std::vector<Override>& overrides, const std::string& fileName) {
    if (place.rfind("--set ", 0) == 0) return "";  // the place names the option already
    for (const auto& o : overrides) {
        std::string pointer = "/" + o.path;
        std::replace(pointer.begin(), pointer.end(), '.', '/');
        if (place == pointer || place.rfind(pointer + "/", 0) == 0) return "--set " + o.path + "=" + o.value;
    }
    return fileName;
}

Override parseOverride(const std::string& text) {
    auto eq = text.find('=');
    if (eq == std::string::npos || eq == 0)
        throw InputError(placeMessage("", "--set " + text, "expected KEY=VALUE, e.g. radiosity.max_edge=0.25"));
    std::string key = text.substr(0, eq);
    if (key.find('/') != std::string::npos) {  // a JSON pointer as printed in error messages
        std::string dotted = key.substr(key.front() == '/' ? 1 : 0);
        std::replace(dotted.begin(), dotted.end(), '/', '.');
        throw InputError(placeMessage("", "--set " + text,
                                      fmt::format("keys are separated by dots: did you mean {}={}?", dotted,
                                                  text.substr(eq + 1))));
    }
    return {key, text.substr(eq + 1)};
}

}  // namespace rayrad::scene
