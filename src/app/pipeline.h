// The pipeline, one call per stage: scene → patches → direct → secondary → sensors → image.
#pragma once

#include <app/glare/observer_glare.h>
#include <app/sensor_table.h>
#include <core/hdr_image.h>
#include <core/output_file.h>
#include <core/stage_report.h>
#include <radiosity/radiosity.h>
#include <raytrace/embree_scene.h>
#include <scene/scene.h>
#include <scene/scene_parser.h>
#include <tonemap/display_transform.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace rayrad::app {

struct PipelineOptions {
    std::vector<scene::Override> overrides;  ///< --set KEY=VALUE
    bool wantImage = false;                  ///< render: run the ray tracer
    bool wantSensors = true;                 ///< evaluate the scene's sensors
    bool observerFisheyes = false;           ///< render each observer's fisheye (--glare-pictures)
    bool quiet = false;                      ///< no progress line
    /// Log error against time at every push-pull (rayrad solve --convergence).
    bool logConvergence = false;
    /// Render this many images during the solve (rayrad render --snapshots), written
    /// next to each of `snapshotOutputs` as NAME.snapKK.EXT.
    int snapshots = 0;
    std::vector<std::string> snapshotOutputs;
    /// Where the snapshots go: their paths (snapshotPath) were added to it before the run.
    OutputFiles* files = nullptr;
    tonemap::DisplayOptions display;
    /// Solve with the emitters of this light group only (scene/light_groups.h).
    std::optional<std::string> lightGroup;
    /// The view the image (and the snapshots) are rendered from; empty: the default.
    std::string view;
    /// A saved solution to use instead of solving (render --solution FILE.rrs).
    std::string solutionFile;
    /// Trace only these rows of the image (render --tile); rowEnd −1: to the last.
    int rowBegin = 0, rowEnd = -1;
};

/// One view's rendering: cd/m² and the average display images are made from.
struct RenderedView {
    std::string name;
    HdrImage image;
    HdrImage displayImage;
};

/// One line of the convergence log, taken at a push-pull.
struct ConvergenceRow {
    double seconds = 0;  ///< solve time so far (logging excluded)
    int64_t shots = 0;
    double unshotFraction = 0;                            ///< of the flux the direct pass left
    std::vector<std::optional<double>> vertexErrorPct;    ///< per referenced sensor
    std::vector<std::optional<double>> gatheredErrorPct;  ///< only at some rows (costly)
};

/// Everything a run produced, and how long each stage took.
struct PipelineRun {
    scene::Scene scene;
    radiosity::PatchMesh mesh;
    bool shadingNormals = false;  ///< mesh.cornerNormal computed (before the first ray trace)
    std::unique_ptr<raytrace::EmbreeScene> embree;
    radiosity::Lighting lighting;  ///< the lights, clusters and solution, and the solve's counts
    std::vector<SensorResult> sensors;
    std::vector<ObserverGlare> glare;      ///< UGR at the scene's observers
    std::optional<HdrImage> image;         ///< cd/m², the plain average of each pixel's samples (EXR, numbers)
    std::optional<HdrImage> displayImage;  ///< the range-compressed average display images are made from
    StageReport report;
    std::vector<std::string> skipped;   ///< "stage (reason)" for the stages not needed
    std::vector<std::string> warnings;  ///< scenes that are probably wrong (sceneWarnings), one line each
    std::vector<ConvergenceRow> convergence;
    std::vector<std::string> convergenceSensors;  ///< names of the sensors with an indirect reference
};

/// Parses and builds the scene (stage "parse").
scene::Scene loadSceneFile(const std::string& file, const std::vector<scene::Override>& overrides);

/// Runs the stages the scene needs. Throws InputError for bad input.
PipelineRun runPipeline(const std::string& sceneFile, const PipelineOptions& options);
/// The same, for a scene the caller has already read from `sceneFile` with
/// options.overrides (the commands read it first to check their outputs): it is not read
/// again (a grid of 10⁶ sensors took 0.45 s to parse).
PipelineRun runPipeline(const std::string& sceneFile, const scene::SceneDesc& desc, const PipelineOptions& options);

/// The energy account of a run's solution against what its lights emit.
radiosity::EnergyBalance energyBalanceOf(const PipelineRun& run);

/// The stages before the lighting (parse and build, premesh, visibility, the scene's
/// warnings), for a caller that solves the lighting itself (the annual study solves it
/// once per sky patch). `inSolid` (if given) gets, per sensor, why it is no measurement.
PipelineRun preparePipeline(const std::string& sceneFile, const scene::SceneDesc& desc, const PipelineOptions& options,
                            std::vector<std::string>* inSolid = nullptr);

/// Ray traces one more view of a solved run (stage "ray trace (NAME)"): a second camera
/// costs a ray trace, not a solve. Throws InputError for a name the scene does not have.
RenderedView renderView(PipelineRun& run, const std::string& view, const PipelineOptions& options);

/// Ray traces one more camera of a solved run (stage "ray trace (LABEL)").
RenderedView renderCamera(PipelineRun& run, const std::string& label, const scene::Camera& camera,
                          const PipelineOptions& options);

/// The scene's view names, for messages: `"a", "b" or "c"`.
std::string viewNames(const scene::Scene& scene);

/// One-paragraph summary of the stages run and skipped, for stderr.
std::string stagesSummary(const PipelineRun& run);

/// The convergence log as CSV: seconds,shots,unshot_pct, then per referenced sensor
/// NAME_vertex_err_pct and NAME_gather_err_pct (indirect light; empty where not computed).
std::string convergenceCsv(const PipelineRun& run);

}  // namespace rayrad::app
