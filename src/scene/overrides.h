// Command-line overrides of scene values (--set radiosity.max_edge=0.25), applied to the
// JSON before it is read. The Override type and parseOverride() are in scene_parser.h.
#pragma once

#include <scene/json_reader.h>
#include <scene/scene_parser.h>

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace rayrad::scene {

/// Sets the value at o.path in `root` (creating objects on the way; array indices must
/// exist). Problems go to `ctx` with the place "--set PATH".
void applyOverride(nlohmann::json& root, const Override& o, ParseContext& ctx);

/// Who gave the value at `place` (a JSON pointer), for messages: "--set PATH=VALUE" when
/// an override set it or a value inside it, "" when the place names the option already,
/// else `fileName`.
std::string sourceOf(const std::string& place, const std::vector<Override>& overrides, const std::string& fileName);

}  // namespace rayrad::scene
