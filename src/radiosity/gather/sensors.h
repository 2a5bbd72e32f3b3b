// Sensors: direct light exactly, indirect by a final gather over the converged solution
// (gather.h), located on the mesh for the limit from inside their own surface.
#pragma once

#include <core/visibility.h>
#include <radiosity/direct/direct_light.h>
#include <radiosity/gather/gather.h>
#include <radiosity/mesh/patch_mesh.h>
#include <radiosity/solution/solution.h>
#include <scene/scene.h>

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace rayrad::radiosity {

/// Illuminance in lx (RGB) at a sensor.
struct SensorValue {
    Rgb direct{0.0};
    Rgb indirect{0.0};                  ///< final gather
    std::optional<Rgb> indirectVertex;  ///< interpolated vertex values, when on a surface
};

/// Direct (exact, `sensorAreaLightSamples` shadow rays per area light), gathered
/// indirect, and vertex-interpolated indirect at a sensor; re-gathers in `memo`.
SensorValue evaluateSensor(const scene::Scene& scene, const PatchMesh& mesh, const RadiositySolution& solution,
                           const DirectLight& lights, const Visibility& vis, const Gatherer& gatherer, GatherMemo& memo,
                           const scene::Sensor& sensor);

/// Every sensor of the scene, in parallel: in runs of consecutive sensors, each run with
/// a memo of its own (a grid's neighbouring points share their re-gathers within a run).
/// The runs are fixed by the sensor count alone (sensorsPerMemo), so the values depend on
/// neither the thread count nor the order the runs finish in. `progress(done, count)` is
/// called under a lock as sensors finish; `gathers` (if given) gets the point gathers taken.
std::vector<SensorValue> evaluateSensors(const scene::Scene& scene, const PatchMesh& mesh,
                                         const RadiositySolution& solution, const DirectLight& lights,
                                         const Visibility& vis, const Gatherer& gatherer,
                                         const std::function<void(size_t, size_t)>& progress, size_t* gathers);

/// The sensor stage measures its cost a sensor once this much CPU time (s) has gone ...
constexpr double kSensorProbeSeconds = 5;
/// ... and warns when all the sensors will take more than this (s).
constexpr double kSlowSensorSeconds = 600;

/// After `done` of `count` sensors took `spentCpu` CPU seconds: a warning with the measured
/// cost a sensor and the CPU-minutes all will take, when that is more than
/// kSlowSensorSeconds (asked only once kSensorProbeSeconds have gone, and not at the end).
std::optional<std::string> slowSensorsWarning(size_t done, size_t count, double spentCpu);

/// Sensors per run of evaluateSensors: about an eighth of them, at least 32. Longer runs
/// share more (the cube's 32 × 32 grid: 9 601 gathers in one run, 10 602 in runs of 129,
/// 12 005 in runs of 64), shorter ones spread better over the cores.
size_t sensorsPerMemo(size_t sensors);

}  // namespace rayrad::radiosity
