// The radiosity stage's front door: prepare the mesh, solve, reconstruct the display values,
// gather at points — one call per sub-stage, in the order of the data flow. Each call reads
// its sub-stage's options from the scene (scene/settings.h) and decides for itself whether
// there is work to do; the sub-stages behind it live in the folders beside this file.
#pragma once

#include <core/stage_report.h>
#include <core/visibility.h>
#include <radiosity/clusters/clusters.h>
#include <radiosity/direct/direct_light.h>
#include <radiosity/direct/openings_leaving.h>
#include <radiosity/display/edge_vertices.h>
#include <radiosity/gather/gather.h>
#include <radiosity/gather/sensors.h>
#include <radiosity/mesh/mesh_location.h>
#include <radiosity/mesh/patch_mesh.h>
#include <radiosity/mesh/patch_reflectance.h>
#include <radiosity/mesh/shading_normals.h>
#include <radiosity/shooting/shooting_solver.h>
#include <radiosity/solution/energy_balance.h>
#include <radiosity/solution/solution.h>
#include <radiosity/solution/solution_file.h>
#include <scene/scene.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace rayrad::radiosity {

/// Where the stage says what it does: each sub-stage it runs begins a stage of `report`
/// (which times it), the ones it leaves out go to `skipped` with the reason, and long ones
/// show a progress line unless `quiet`. Every pointer may be null.
struct StageLog {
    StageReport* report = nullptr;
    std::vector<std::string>* skipped = nullptr;  ///< "stage (reason)"
    bool quiet = true;
    /// Warnings found while the stage runs (a sensor stage that will take long), without
    /// the "warning: FILE: " prefix; also printed so when not quiet.
    std::vector<std::string>* warnings = nullptr;
    void begin(const std::string& stage) const;
    void skip(const std::string& what) const;
    void warn(const std::string& file, const std::string& what) const;
};

/// The lighting of a scene as the stage computes it: the lights, the clusters, the solution,
/// and what the sub-stages counted on the way.
struct Lighting {
    std::unique_ptr<DirectLight> lights;
    /// Built by the first sub-stage that needs it (the shooting, a gather); empty before.
    Clustering clustering;
    RadiositySolution solution;
    ShootingStatistics shooting;
    double maxIlluminanceStep = 0;     ///< ΔI_max the shooting used, lx
    bool singleChannel = false;        ///< the scene is grey: one channel was solved
    GatheredVertices displayVertices;  ///< vertices whose display value came from a point gather
    size_t seamProfileGathers = 0;     ///< point gathers the seam profiles took
    size_t sensorGathers = 0;          ///< point gathers the sensors took (their own and every re-gather)
    /// Image chains of the image method (the lights know them).
    size_t mirrorImages() const { return lights ? lights->imageCount() : 0; }
};

// 1. The mesh.

/// Estimated patches and the edge the premesher would aim for, before any is made (absurd
/// settings are caught before they are tried).
struct MeshEstimate {
    double patches = 0;
    double edgeLength = 0;  ///< m
};
MeshEstimate estimateMesh(const scene::Scene& scene);

/// The scene's surfaces premeshed into patches (scene.meshing), with their textures' means
/// (stages "premesh", "texture means"). Build the visibility over it, then findContacts().
PatchMesh prepareMesh(const scene::Scene& scene, const StageLog& log);

/// What the visibility finds on the mesh: where a surface stands on a patch off its mesh
/// lines (contact outlines), and patches with a surface just in front of them (covered).
void findContacts(PatchMesh& mesh, const scene::Scene& scene, const Visibility& vis);

// 2. The solve.

/// The direct light at every patch's centroid and corners (stage "direct light"), and the
/// lights every later stage evaluates (with virtual lights for the mirrors' images).
Lighting solveDirect(const scene::Scene& scene, const PatchMesh& mesh, const Visibility& vis, const StageLog& log);

/// What is called at every push-pull of the shooting (ShootingSolver::PushPullHook); the
/// clusters are in lighting.clustering then.
using PushPullHook = ShootingSolver::PushPullHook;

/// The indirect light: the clusters, then shooting until radiosity.stop_unshot (stages
/// "clusters", "secondary pass (shooting)"); with no reflecting surface, none at all.
/// `onProgress` as ShootingSolver::solve (the caller shows it).
void solveIndirect(const scene::Scene& scene, const PatchMesh& mesh, const Visibility& vis, Lighting& lighting,
                   const StageLog& log, const PushPullHook& onPushPull = {});

/// A saved solution in place of the solve (render --solution): checked against the scene
/// and mesh (fingerprintOf); throws InputError naming `path` when it does not fit.
Lighting loadSolution(const scene::Scene& scene, const PatchMesh& mesh, const std::string& bytes,
                      const std::string& path, const StageLog& log);

/// The lights of `scene` as it is now, with a solution computed elsewhere in place of a solve
/// (an hour's weighted sum of daylight channels' solutions): what reconstructDisplay and the
/// ray tracer need. The openings' entering light is measured as solveDirect does.
Lighting lightingWith(const scene::Scene& scene, const Visibility& vis, RadiositySolution solution);

// 3. The display values.

/// What the image interpolates between (stage "reconstruct vertices"): vertex values from
/// the patches (scene.reconstruction), then point gathers at concave seams, beside contact
/// outlines and covered parts, and the seam profiles. Needs the solve's indirect light.
void reconstructDisplay(const scene::Scene& scene, const PatchMesh& mesh, const Visibility& vis, Lighting& lighting,
                        const StageLog& log);

/// The vertex values alone, from the patches (no gathers): for a solution being watched
/// while it converges (a copy of lighting.solution).
void reconstructVertexValues(const scene::Scene& scene, const PatchMesh& mesh, RadiositySolution& solution);

// 4. Gathers at points.

/// The clusters, built now if no sub-stage has built them (stage "clusters").
const Clustering& clustersOf(const scene::Scene& scene, const PatchMesh& mesh, const Visibility& vis,
                             Lighting& lighting, const StageLog& log);

/// The final gather as the sensors use it (scene.gather), over the solution in `lighting`.
std::unique_ptr<Gatherer> sensorGatherer(const scene::Scene& scene, const PatchMesh& mesh, const Visibility& vis,
                                         Lighting& lighting, const StageLog& log);

/// Every sensor of the scene: direct light exactly, indirect by the final gather (stage
/// "sensors (N)"; lighting.sensorGathers counts the gathers), with slowSensorsWarning's
/// warning once the sensors done say that all will take long.
std::vector<SensorValue> gatherSensors(const scene::Scene& scene, const PatchMesh& mesh, const Visibility& vis,
                                       Lighting& lighting, const StageLog& log);

/// One point that is not among the scene's sensors (an observer's eye), as a sensor reads
/// it, with `gatherer` (sensorGatherer's).
SensorValue evaluatePoint(const scene::Scene& scene, const PatchMesh& mesh, const Visibility& vis,
                          const Lighting& lighting, const Gatherer& gatherer, const scene::Sensor& point);


}  // namespace rayrad::radiosity
