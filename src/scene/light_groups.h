// Light groups (light scenes): emitters carry a group name, and because the light is
// linear in the emission, a solve per group tells a designer what each group adds
// everywhere; dimming a group afterwards is scaling its part.
#pragma once

#include <scene/scene.h>

#include <string>
#include <vector>

namespace rayrad::scene {

/// The scene's light groups in the order they first appear among the lights and then the
/// emissive materials; "" (the emitters in no group) first when there are any. Empty when
/// no emitter names a group.
std::vector<std::string> lightGroups(const Scene& scene);

/// Keeps only the emitters of `group`: the other point lights and luminaires removed, the
/// other emissive materials no longer emitting (they still reflect).
void keepLightGroup(Scene& scene, const std::string& group);

/// Removes every electric light (point lights, luminaires, emissive materials stop
/// emitting): the daylight alone is left.
void removeElectricLight(Scene& scene);

}  // namespace rayrad::scene
