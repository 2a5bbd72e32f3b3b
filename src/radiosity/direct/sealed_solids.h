// Which surfaces bound a sealed solid: the direct pass need not light their backs.
#pragma once

#include <scene/scene.h>

#include <vector>

namespace rayrad::radiosity {

/// Per surface group: 1 when all its polygons belong to a sealed solid — a connected,
/// closed surface of diffuse polygons (among every group's, so a box's six faces count
/// together), each edge used once in each direction (consistently wound, no gap, no
/// fourth face on an edge), whose bounds hold no light source (a point light, a
/// luminaire's opening, an emitter's vertex). Its surfaces' backs face its inside, which no
/// light reaches: the direct pass skips them (in the hall, the desks' and cabinets' faces,
/// half the troffers in front of each back and every ray ending on the box). Anything
/// else — an open mesh, a shared or non-manifold edge, glass or a mirror in the surface, a
/// lamp inside — keeps its backs lit as before.
std::vector<char> sealedGroups(const scene::Scene& scene);

}  // namespace rayrad::radiosity
