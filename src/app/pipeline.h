// The pipeline, one call per stage: scene → patches → direct → secondary → sensors → image.
#pragma once

#include <app/sensor_table.h>
#include <core/hdr_image.h>
#include <core/stage_report.h>
#include <radiosity/clusters.h>
#include <radiosity/direct_light.h>
#include <radiosity/shooting_solver.h>
#include <radiosity/patch_mesh.h>
#include <radiosity/solution.h>
#include <raytrace/embree_scene.h>
#include <scene/scene.h>
#include <scene/scene_parser.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace rayrad::app {

struct PipelineOptions {
    std::vector<scene::Override> overrides;  ///< --set KEY=VALUE
    bool wantImage = false;                  ///< render: run the ray tracer
    bool wantSensors = true;                 ///< evaluate the scene's sensors
    bool quiet = false;                      ///< no progress line
};

/// Everything a run produced, and how long each stage took.
struct PipelineRun {
    scene::Scene scene;
    radiosity::PatchMesh mesh;
    radiosity::Clustering clustering;
    radiosity::ShootingStatistics shooting;
    double maxIlluminanceStep = 0;  ///< ΔI_max used, lx
    std::unique_ptr<raytrace::EmbreeScene> embree;
    std::unique_ptr<radiosity::DirectLight> lights;
    radiosity::RadiositySolution solution;
    std::vector<SensorResult> sensors;
    std::optional<HdrImage> image;
    StageReport report;
    std::vector<std::string> skipped;  ///< "stage (reason)" for the stages not needed
};

/// Parses and builds the scene (stage "parse").
scene::Scene loadSceneFile(const std::string& file, const std::vector<scene::Override>& overrides);

/// Runs the stages the scene needs. Throws InputError for bad input.
PipelineRun runPipeline(const std::string& sceneFile, const PipelineOptions& options);

/// One-paragraph summary of the stages run and skipped, for stderr.
std::string stagesSummary(const PipelineRun& run);

}  // namespace rayrad::app
