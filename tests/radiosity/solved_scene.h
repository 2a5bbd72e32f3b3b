// A scene solved through the radiosity stage's front door (radiosity/radiosity.h), without the
// app's pipeline: the radiosity tests' way to a mesh, a solution and sensor values.
#pragma once

#include <radiosity/radiosity.h>
#include <raytrace/embree_scene.h>
#include <scene/scene.h>
#include <scene/scene_parser.h>

#include <memory>
#include <string>
#include <vector>

namespace rayrad::test {

struct SolvedScene {
    /// A sensor and what the stage gathered there.
    struct Sensor {
        scene::Sensor sensor;
        radiosity::SensorValue value;
    };
    scene::Scene scene;
    radiosity::PatchMesh mesh;
    std::unique_ptr<raytrace::EmbreeScene> embree;
    radiosity::Lighting lighting;
    std::vector<Sensor> sensors;
};

/// Reads `file` with `overrides` (as --set), then runs the stage's sub-stages in order:
/// the mesh, the visibility over it, the contacts, the direct and the indirect light, the
/// display values, and the sensors (when the scene has some and `sensors` is true).
inline SolvedScene solve(const std::string& file, const std::vector<scene::Override>& overrides = {},
                         bool sensors = true) {
    SolvedScene s;
    s.scene = scene::buildScene(scene::loadScene(file, overrides));
    const radiosity::StageLog quiet;
    s.mesh = radiosity::prepareMesh(s.scene, quiet);
    s.embree = raytrace::buildEmbreeScene(s.scene, s.mesh);
    radiosity::findContacts(s.mesh, s.scene, *s.embree);
    s.lighting = radiosity::solveDirect(s.scene, s.mesh, *s.embree, quiet);
    radiosity::solveIndirect(s.scene, s.mesh, *s.embree, s.lighting, quiet);
    radiosity::reconstructDisplay(s.scene, s.mesh, *s.embree, s.lighting, quiet);
    if (sensors) {
        const auto values = radiosity::gatherSensors(s.scene, s.mesh, *s.embree, s.lighting, quiet);
        for (size_t i = 0; i < values.size(); ++i) s.sensors.push_back({s.scene.sensors[i], values[i]});
    }
    return s;
}

}  // namespace rayrad::test
