// render --camera: which of the scene's named views to render, and where each one's
// images go.
#pragma once

#include <scene/scene_desc.h>

#include <string>
#include <vector>

namespace rayrad::app {

/// The views to render, in the scene's order: `requested` names (or "all"); none
/// requested: the default view. Throws InputError for a name the scene does not have
/// (listing its names) or a scene without a camera.
std::vector<std::string> selectViews(const scene::SceneDesc& desc, const std::vector<std::string>& requested);

/// Where a view's image goes when several are rendered: "out/room.png" + "entrance" →
/// "out/room.entrance.png"; the path itself when only one is.
std::string viewPath(const std::string& path, const std::string& view, size_t viewCount);

}  // namespace rayrad::app
