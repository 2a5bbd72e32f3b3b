#include <radiosity/radiosity.h>

#include <core/input_error.h>
#include <core/progress.h>
#include <radiosity/direct/direct_pass.h>
#include <radiosity/display/seam_profile_gathers.h>
#include <radiosity/display/vertex_reconstruction.h>
#include <radiosity/mesh/contact_outlines.h>
#include <radiosity/mesh/covered_patches.h>
#include <radiosity/mesh/mesher.h>

#include <fmt/format.h>

#include <cmath>

namespace rayrad::radiosity {

void StageLog::begin(const std::string& stage) const {
    if (report) report->begin(stage);
}

void StageLog::skip(const std::string& what) const {
    if (skipped) skipped->push_back(what);
}

void StageLog::warn(const std::string& file, const std::string& what) const {
    if (!quiet) fmt::print(stderr, "warning: {}: {}\n", file, what);
    if (warnings) warnings->push_back(what);
}

MeshEstimate estimateMesh(const scene::Scene& scene) {
    return {estimatePatchCount(scene, scene.meshing), targetEdge(scene, scene.meshing)};
}

PatchMesh prepareMesh(const scene::Scene& scene, const StageLog& log) {
    log.begin("premesh");
    PatchMesh mesh;
    {
        Progress progress("premesh", log.quiet);
        mesh = premesh(scene, scene.meshing, [&](double f) { progress.update(f); });
    }
    if (!scene.textures.empty()) {
        log.begin(fmt::format("texture means ({} images)", scene.textures.size()));
        computeTexturedReflectance(scene, mesh);
    }
    return mesh;
}

void findContacts(PatchMesh& mesh, const scene::Scene& scene, const Visibility& vis) {
    findContactOutlines(mesh, vis, kContactTolerance * scene.diagonal(), pointNudge(scene));
    mesh.covered = coveredPatches(mesh, vis, kCoverLift * scene.diagonal());
}

Lighting solveDirect(const scene::Scene& scene, const PatchMesh& mesh, const Visibility& vis, const StageLog& log) {
    Lighting lighting =
        lightingWith(scene, vis, RadiositySolution{});  // the lights; daylight: what the openings let in
    if (scene.mirrors.empty())
        log.skip("virtual lights and shooters (no mirrors)");
    else if (!scene.mirrorImages.imageMethod())
        log.skip("virtual lights and shooters (mirrors ignored)");
    log.begin(lighting.mirrorImages() > 0 ? fmt::format("direct light (+{} virtual lights in {} mirror images)",
                                                        lighting.lights->virtualLightCount(), lighting.mirrorImages())
                                          : std::string("direct light"));
    Progress progress("direct light", log.quiet);
    computeDirect(scene, mesh, *lighting.lights, vis, scene.direct.areaLightSamples, lighting.solution,
                  [&](double f) { progress.update(f); });
    lighting.solution.passedThrough = lighting.lights->passingThrough();
    return lighting;
}

Lighting lightingWith(const scene::Scene& scene, const Visibility& vis, RadiositySolution solution) {
    Lighting lighting;
    lighting.lights = std::make_unique<DirectLight>(scene);
    lighting.lights->measureEntering(vis);
    lighting.solution = std::move(solution);
    return lighting;
}

const Clustering& clustersOf(const scene::Scene& scene, const PatchMesh& mesh, const Visibility& vis,
                             Lighting& lighting, const StageLog& log) {
    if (lighting.clustering.clusters.empty() && !mesh.patches.empty()) {
        log.begin("clusters");
        lighting.clustering = buildClusters(scene, mesh, scene.clusters, &vis);
    }
    return lighting.clustering;
}

void solveIndirect(const scene::Scene& scene, const PatchMesh& mesh, const Visibility& vis, Lighting& lighting,
                   const StageLog& log, const PushPullHook& onPushPull) {
    RadiositySolution& solution = lighting.solution;
    if (!scene.hasReflectance()) {
        // Nothing reflects: the solution is complete with no indirect light at all.
        solution.indirect.assign(mesh.patches.size(), Rgb(0.0));
        solution.converged = true;
        log.skip("secondary pass (no surface reflects light)");
        return;
    }
    const Clustering& clustering = clustersOf(scene, mesh, vis, lighting, log);
    log.begin("secondary pass (shooting)");
    ShootingSolver solver(scene, mesh, clustering, vis);
    solver.initialize(solution);
    Progress progress("secondary pass", log.quiet);
    solver.solve(solution, onPushPull, [&](const RadiositySolution& s) {
        // Progress in log space from the first reflection down to the stopping threshold
        // (radiosity.stop_unshot × the emitted flux).
        if (!(s.initialUnshotFlux > 0)) return;  // nothing to shoot: converged at once
        const double left = s.remainingUnshotFlux / s.initialUnshotFlux;
        const double target = scene.shooting.stopUnshot * s.unshotReference() / s.initialUnshotFlux;
        const double done = left > 0 && target < 1 ? std::log(left) / std::log(target) : 1.0;
        progress.update(done, fmt::format("{} shots, unshot {:.3g}%", s.shots, 100 * s.unshotFraction()));
    });
    lighting.shooting = solver.statistics();
    lighting.maxIlluminanceStep = solver.maxIlluminanceStep();
    lighting.singleChannel = solver.singleChannel();
    solution.leftThroughOpenings = leavingThroughOpenings(scene, mesh, solution, *lighting.lights, vis);
}

Lighting loadSolution(const scene::Scene& scene, const PatchMesh& mesh, const std::string& bytes,
                      const std::string& path, const StageLog& log) {
    log.begin("load solution");
    Lighting lighting;
    lighting.lights = std::make_unique<DirectLight>(scene);
    lighting.solution =
        decodeSolution(bytes, path, fingerprintOf(scene, mesh), mesh.patches.size(), mesh.vertices.size());
    lighting.solution.seamProfiles.index(mesh);
    log.skip("direct light and secondary pass (solution read from " + path + ")");
    return lighting;
}

void reconstructVertexValues(const scene::Scene& scene, const PatchMesh& mesh, RadiositySolution& solution) {
    reconstructVertices(mesh, solution, scene.reconstruction.linear());
}

void reconstructDisplay(const scene::Scene& scene, const PatchMesh& mesh, const Visibility& vis, Lighting& lighting,
                        const StageLog& log) {
    log.begin("reconstruct vertices");
    RadiositySolution& solution = lighting.solution;
    if (!scene.hasReflectance()) {
        reconstructVertices(mesh, solution);  // all zero
        return;
    }
    reconstructVertexValues(scene, mesh, solution);
    const auto& options = scene.reconstruction;
    if (options.edgeGatherLevels <= 0) return;
    const Clustering& clustering = clustersOf(scene, mesh, vis, lighting, log);
    {
        Progress progress("seam vertices", log.quiet);
        lighting.displayVertices = gatherEdgeVertices(scene, mesh, clustering, solution, vis, options.edgeGatherLevels,
                                                      [&](double f) { progress.update(f); });
    }
    if (options.seamProfileNodes <= 0 || lighting.displayVertices.seamVertices.empty()) return;
    Progress progress("seam profiles", log.quiet);
    // Edges as short as an input mesh's own detail are left linear, as the contacts are.
    const double minEdge = kContactMinEdges * mesh.edgeLength;
    solution.seamProfiles =
        gatherSeamProfiles(scene, mesh, clustering, solution, vis, lighting.displayVertices.seamVertices,
                           lighting.displayVertices.seamsGatheredAside, minEdge, options.seamProfileNodes,
                           &lighting.seamProfileGathers, [&](double f) { progress.update(f); });
}

std::unique_ptr<Gatherer> sensorGatherer(const scene::Scene& scene, const PatchMesh& mesh, const Visibility& vis,
                                         Lighting& lighting, const StageLog& log) {
    const Clustering& clustering = clustersOf(scene, mesh, vis, lighting, log);
    return std::make_unique<Gatherer>(scene, mesh, clustering, lighting.solution, vis,
                                      GatherOptions::forSensors(scene, mesh));
}

std::vector<SensorValue> gatherSensors(const scene::Scene& scene, const PatchMesh& mesh, const Visibility& vis,
                                       Lighting& lighting, const StageLog& log) {
    if (scene.sensors.empty()) return {};
    const auto gatherer = sensorGatherer(scene, mesh, vis, lighting, log);
    log.begin(fmt::format("sensors ({})", scene.sensors.size()));
    Progress progress("sensors", log.quiet);
    // The cost a sensor is measured, not guessed (called under evaluateSensors' lock).
    const double start = processCpuSeconds();
    bool warned = false;
    return evaluateSensors(
        scene, mesh, lighting.solution, *lighting.lights, vis, *gatherer,
        [&](size_t done, size_t count) {
            progress.update(static_cast<double>(done) / count, fmt::format("{} of {}", done, count));
            if (warned) return;
            if (auto w = slowSensorsWarning(done, count, processCpuSeconds() - start)) {
                warned = true;
                log.warn(scene.file, *w);
            }
        },
        &lighting.sensorGathers);
}

SensorValue evaluatePoint(const scene::Scene& scene, const PatchMesh& mesh, const Visibility& vis,
                          const Lighting& lighting, const Gatherer& gatherer, const scene::Sensor& point) {
    GatherMemo memo;
    return evaluateSensor(scene, mesh, lighting.solution, *lighting.lights, vis, gatherer, memo, point);
}

}  // namespace rayrad::radiosity
