// Warnings for scenes that are probably wrong: lights, cameras and sensors buried in
// solids or behind mirrors, mirrors that face nothing. One line each, before any work.
#pragma once

#include <radiosity/radiosity.h>
#include <raytrace/embree_scene.h>
#include <scene/scene.h>

#include <optional>
#include <string>
#include <vector>

namespace rayrad::app {

/// Casts a few dozen rays from each light, the camera, each sensor and each mirror and
/// says, one line each, what looks wrong:
///  - a point light, area light, camera or sensor inside a closed solid (its rays hit
///    the inside of surfaces), or a camera that looks at the back of a mirror;
///  - a sensor that is buried (its hemisphere covered within a few millimetres: it
///    will read about 0) or behind a mirror;
///  - a mirror whose front faces nothing (wound backwards, or against a wall).
/// `checkSensors` false: the sensors are not looked at (a render that does not gather them).
/// `inSolid` (optional, with checkSensors): per sensor, why it is no measurement — "inside
/// a solid" or "buried" (under a surface within a few millimetres) — or "".
std::vector<std::string> sceneWarnings(const scene::Scene& scene, const radiosity::PatchMesh& mesh,
                                       const raytrace::EmbreeScene& embree, bool checkSensors = true,
                                       std::vector<std::string>* inSolid = nullptr);

/// Why a point is inside a closed solid — "N of 64 rays from it hit the inside of
/// surfaces" — or nothing when it is not (the probe sceneWarnings uses for lights).
std::optional<std::string> insideSolid(const scene::Scene& scene, const radiosity::PatchMesh& mesh,
                                       const raytrace::EmbreeScene& embree, const Vec3& point);

/// Above this share of the emitted flux, light on the backs of one-sided surfaces is
/// worth a warning.
constexpr double kBackLightShare = 1e-3;

/// After the direct pass: a warning when more than kBackLightShare of the emitted flux
/// fell on the backs of one-sided surfaces, naming the surface that took most of it.
std::optional<std::string> backLightWarning(const scene::Scene& scene, const radiosity::RadiositySolution& solution,
                                            double emittedFlux);

}  // namespace rayrad::app
