#include <app/pipeline.h>

#include <core/progress.h>
#include <radiosity/direct_pass.h>
#include <radiosity/gather.h>
#include <radiosity/mesher.h>
#include <radiosity/shooting_solver.h>
#include <raytrace/camera.h>
#include <raytrace/ray_tracer.h>

#include <fmt/format.h>

#include <mutex>

namespace rayrad::app {

scene::Scene loadSceneFile(const std::string& file, const std::vector<scene::Override>& overrides) {
    return scene::buildScene(scene::loadScene(file, overrides));
}

namespace {

void solveSecondary(PipelineRun& run, bool quiet) {
    radiosity::ShootingSolver solver(run.scene, run.mesh, run.clustering, *run.embree, run.scene.solver,
                                     run.scene.clusters);
    solver.initialize(run.solution);
    Progress progress("secondary pass", quiet);
    double target = run.scene.solver.stopUnshot;
    solver.solve(run.solution, {}, [&](const radiosity::RadiositySolution& s) {
        double frac = s.initialUnshotFlux > 0 ? s.remainingUnshotFlux / s.initialUnshotFlux : 0;
        // Progress in log space from 1 down to the stopping threshold.
        double done = frac > 0 ? std::log(frac) / std::log(target) : 1.0;
        progress.update(done, fmt::format("{} shots, unshot {:.3g}%", s.shots, 100 * frac));
    });
    run.shooting = solver.statistics();
    run.maxIlluminanceStep = solver.maxIlluminanceStep();
}

}  // namespace

PipelineRun runPipeline(const std::string& sceneFile, const PipelineOptions& options) {
    PipelineRun run;
    run.report.begin("parse + build scene");
    run.scene = loadSceneFile(sceneFile, options.overrides);

    run.report.begin("premesh");
    run.mesh = radiosity::premesh(run.scene, run.scene.meshing);

    run.report.begin("visibility (Embree BVH)");
    run.embree = std::make_unique<raytrace::EmbreeScene>(run.mesh, 1e-5 * run.scene.diagonal());

    run.report.begin("direct light");
    run.lights = std::make_unique<radiosity::DirectLight>(run.scene);
    radiosity::computeDirect(run.mesh, *run.lights, *run.embree, run.scene.solver.areaLightSamples, run.solution);

    if (run.scene.hasReflectance()) {
        run.report.begin("clusters");
        run.clustering = radiosity::buildClusters(run.scene, run.mesh, run.scene.clusters);
        run.report.begin("secondary pass (shooting)");
        solveSecondary(run, options.quiet);
        run.report.begin("reconstruct vertices");
        radiosity::reconstructVertices(run.mesh, run.solution, run.scene.solver.linearReconstruction);
    } else {
        run.skipped.push_back("secondary pass (no surface reflects light)");
    }

    if (options.wantSensors && !run.scene.sensors.empty()) {
        run.report.begin(fmt::format("sensors ({})", run.scene.sensors.size()));
        if (run.clustering.clusters.empty())  // no secondary pass: the gather finds nothing to gather
            run.clustering = radiosity::buildClusters(run.scene, run.mesh, run.scene.clusters);
        radiosity::Gatherer gatherer(run.scene, run.mesh, run.clustering, run.solution, *run.embree,
                                     run.scene.solver.gatherLevels);
        for (const auto& s : run.scene.sensors)
            run.sensors.push_back({s, radiosity::evaluateSensor(run.scene, run.mesh, run.solution, *run.lights,
                                                                *run.embree, gatherer, s)});
    } else if (options.wantSensors) {
        run.skipped.push_back("sensors (the scene has none)");
    }

    if (options.wantImage) {
        run.report.begin("ray trace");
        raytrace::PinholeCamera camera(*run.scene.camera);
        Progress progress("ray trace", options.quiet);
        std::mutex m;
        run.image = raytrace::render(run.scene, run.mesh, run.solution, *run.lights, *run.embree, camera,
                                     run.scene.render, [&](double f) {
                                         std::lock_guard<std::mutex> lock(m);
                                         progress.update(f);
                                     });
    } else if (!run.scene.camera) {
        run.skipped.push_back("ray trace (no camera)");
    }
    run.report.end();
    return run;
}

std::string stagesSummary(const PipelineRun& run) {
    std::string s = "stages run:";
    for (const auto& st : run.report.stages()) s += " " + st.name + ";";
    if (!run.skipped.empty()) {
        s += "\nstages skipped:";
        for (const auto& k : run.skipped) s += " " + k + ";";
    }
    return s + "\n";
}

}  // namespace rayrad::app
