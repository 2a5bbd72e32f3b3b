// rayrad: parse, build, solve, render, write — one call per stage (see app/pipeline.h).
#include <app/image_output.h>
#include <app/result_checks.h>
#include <app/validate_runs.h>
#include <app/version.h>
#include <app/pipeline.h>
#include <app/run_outputs.h>
#include <app/validate_cube.h>
#include <app/compare.h>
#include <app/validate_luminaire.h>
#include <app/scene_info.h>
#include <app/tiles.h>
#include <app/views.h>
#include <app/walkthrough.h>
#include <app/sweep.h>
#include <app/lit_mesh_export.h>
#include <radiosity/radiosity.h>
#include <app/validate_sphere.h>
#include <app/sensor_table.h>
#include <app/solve_summary.h>
#include <core/input_error.h>
#include <core/output_file.h>
#include <core/result_error.h>
#include <core/text.h>
#include <tonemap/display_transform.h>
#include <tonemap/image_io.h>

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <limits>
#include <iostream>
#include <memory>

using namespace rayrad;

namespace {

// Exit codes (docs/cli.md): 0 done, 1 internal error, 2 bad input (scene, options),
// 3 an output cannot be written, 4 the result is not usable (non-finite, all black).
constexpr int kExitInternalError = 1;
constexpr int kExitInputError = 2;
constexpr int kExitOutputError = 3;
constexpr int kExitResultError = 4;
constexpr int kMaxThreads = 4096;

struct CommonArgs {
    std::string scene;
    std::vector<std::string> sets;
    int threads = 0;
    bool quiet = false;
};

void addCommon(CLI::App* cmd, CommonArgs& a) {
    cmd->add_option("scene", a.scene, "Scene file (JSON, see docs/scene-format.md); - reads it from standard input")->required();
    cmd->add_option("--set", a.sets, "Override a scene value, e.g. --set radiosity.max_edge=0.25 (repeatable)");
    cmd->add_option("--threads", a.threads, "Worker threads (default 0: all cores)")->check(CLI::Range(0, kMaxThreads));
    cmd->add_flag("-q,--quiet", a.quiet, "No progress line");
}

std::vector<scene::Override> overridesOf(const CommonArgs& a) {
    std::vector<scene::Override> out;
    for (const auto& s : a.sets) out.push_back(scene::parseOverride(s));
    return out;
}

int runSolve(const CommonArgs& a, const std::string& csv, const app::ReportArgs& reports, const std::string& save) {
    app::PipelineOptions o;
    o.overrides = overridesOf(a);
    o.quiet = a.quiet;
    o.logConvergence = !reports.convergence.empty();
    // Read and check the scene, then every output, before any work.
    const auto desc = scene::loadScene(a.scene, o.overrides);
    OutputFiles files = app::filesOf(desc);
    const app::SensorFiles csvs = app::sensorFiles(desc, csv);
    std::vector<std::string> outputs = app::addSensorAndReportOutputs(desc, csvs, reports, files);
    app::addOutputs(files, {save});
    auto run = app::runPipeline(a.scene, desc, o);
    // With light groups, the saved solution also holds each group's part, so a scene whose
    // groups are dimmed can be rendered from it.
    auto groups = app::reportSensors(run, a.scene, o, csvs, files, !save.empty());
    if (!save.empty())
        files.set(save, radiosity::encodeSolution(run.lighting.solution, radiosity::fingerprintOf(run.scene, run.mesh),
                                                  run.mesh.vertices.size(),
                                                  groups ? groups->solutions : std::vector<radiosity::GroupSolution>{}));
    if (groups && run.sensors.empty()) groups.reset();  // parts for the file only
    app::stageReports(run, a.scene, reports, groups ? &*groups : nullptr, files);
    files.commit();
    outputs.push_back(save);
    app::reportWritten(outputs);
    app::printSolveSummary(run);
    std::cerr << app::stagesSummary(run) << run.report.toString();
    return 0;
}

/// render --frames: one solve (or a saved solution), then a ray trace for each frame of the
/// scene's camera path. Each frame's images are written as soon as it is done (a long
/// walkthrough keeps what it has finished), all exposed alike (steadyDisplay).
int runFrames(const CommonArgs& a, app::PipelineOptions o, const std::vector<std::string>& images,
              const std::string& framesText, const tonemap::DisplayOptions& display, bool allowBlack) {
    const auto desc = scene::loadScene(a.scene, o.overrides);
    const auto [first, last] = app::parseFrames(framesText, desc.cameraPath ? desc.cameraPath->frames : 0, a.scene);
    OutputFiles files = app::filesOf(desc);
    if (!o.solutionFile.empty()) files.addInput(o.solutionFile);
    std::vector<std::vector<std::string>> frameImages;
    for (int k = first; k <= last; ++k) {
        std::vector<std::string> paths;
        for (const auto& path : images) paths.push_back(app::framePath(path, k));
        app::addImageOutputs(paths, files);
        frameImages.push_back(paths);
    }
    o.wantImage = false;
    o.wantSensors = false;
    auto run = app::runPipeline(a.scene, desc, o);
    const tonemap::DisplayOptions steady =
        app::steadyDisplay(app::viewsAdaptationLuminance(run, run.scene.pathFrames, o), display);
    for (int k = first; k <= last; ++k) {
        const auto& paths = frameImages[static_cast<size_t>(k - first)];
        const auto view = app::renderCamera(run, fmt::format("frame {}, {} of {}", k, k - first + 1, last - first + 1),
                                            run.scene.pathFrames[static_cast<size_t>(k)], o);
        app::checkRenderedImage(view.image, allowBlack);
        app::stageImages(paths, view.image, view.displayImage, steady, fmt::format("rayrad rendering of {}, frame {}", a.scene, k),
                         files);
        files.commit();
        if (!a.quiet) app::reportWritten(paths);
    }
    app::printSolveSummary(run);
    std::cerr << app::stagesSummary(run) << run.report.toString();
    return 0;
}

int runRender(const CommonArgs& a, const std::vector<std::string>& images, const std::string& csv,
              std::optional<int> spp, std::optional<int> seed, const std::string& exposure,
              const tonemap::DisplayOptions& displayIn, int snapshots, bool allowBlack, const app::ReportArgs& reports,
              const std::vector<std::string>& cameras, const std::string& solution, const std::string& tileText,
              const std::string& framesText) {
    const tonemap::DisplayOptions display = tonemap::parseExposure(exposure, displayIn);
    if (const auto warning = tonemap::checkDisplayOptions(display)) fmt::print(stderr, "warning: {}\n", *warning);
    app::PipelineOptions o;
    o.overrides = overridesOf(a);
    if (spp) o.overrides.push_back({"render.spp", std::to_string(*spp)});
    if (seed) o.overrides.push_back({"render.seed", std::to_string(*seed)});
    o.quiet = a.quiet;
    o.wantImage = true;
    // Sensors only when something reports them.
    o.wantSensors = !csv.empty() || !reports.report.empty() || !reports.gridPicture.empty();
    o.logConvergence = !reports.convergence.empty();
    o.snapshots = snapshots;
    o.display = display;
    o.solutionFile = solution;
    const app::Tile tile = tileText.empty() ? app::Tile{} : app::parseTile(tileText);
    if (tile.count > 0) {
        for (const auto& path : images)
            if (!tonemap::isHdrFormat(path))
                throw InputError(placeMessage(path, "--tile", "a tile is written as EXR (rayrad merge makes the PNG or JPEG)"));
        if (snapshots > 0) throw InputError(placeMessage("", "--tile", "snapshots are of whole images: render them without --tile"));
        if (!reports.falseColour.empty()) throw InputError(placeMessage("", "--tile", "a false-colour picture is of the whole image"));
    }
    if (!solution.empty() && snapshots > 0)
        throw InputError(placeMessage("", "--snapshots", "a saved solution (--solution) has no solve to take snapshots of"));
    if (!framesText.empty()) {
        const std::vector<std::pair<bool, const char*>> alone = {
            {!cameras.empty(), "--camera"}, {tile.count > 0, "--tile"}, {snapshots > 0, "--snapshots"},
            {!reports.falseColour.empty(), "--false-colour"}, {o.wantSensors || o.logConvergence, "--sensors, --report, "
                                                                                                  "--grid-picture or --convergence"}};
        for (const auto& [given, option] : alone)
            if (given)
                throw InputError(placeMessage("", "--frames", std::string("renders the camera path's frames alone: not with ") + option));
        return runFrames(a, o, images, framesText, display, allowBlack);
    }
    // Read and check the scene, then every output, before any work.
    const auto desc = scene::loadScene(a.scene, o.overrides);
    const std::vector<std::string> views = app::selectViews(desc, cameras);
    o.view = views.front();
    if (tile.count > 0 && views.size() > 1)
        throw InputError(placeMessage("", "--tile", "tiles are of one view: give one --camera"));
    for (const auto& [name, c] : desc.views)
        if (name == o.view) std::tie(o.rowBegin, o.rowEnd) = app::tileRows(tile, c.height);
    std::vector<std::vector<std::string>> viewImages;  // per view, its output paths
    for (const auto& v : views) {
        std::vector<std::string> paths;
        for (const auto& path : images) paths.push_back(app::viewPath(path, v, views.size()));
        viewImages.push_back(paths);
        for (const auto& [name, c] : desc.views)
            if (name == v) tonemap::checkWhiteBalance(display.whiteBalance, c.width, c.height);
    }
    o.snapshotOutputs = viewImages.front();
    OutputFiles files = app::filesOf(desc);
    if (!solution.empty()) files.addInput(solution);
    for (const auto& paths : viewImages) app::addImageOutputs(paths, files);
    for (int k = 1; k <= snapshots; ++k)
        for (const auto& path : viewImages.front()) files.add(app::snapshotPath(path, k));
    const app::SensorFiles csvs = app::sensorFiles(desc, csv);
    const std::vector<std::string> others = app::addSensorAndReportOutputs(desc, csvs, reports, files);
    o.files = &files;
    auto run = app::runPipeline(a.scene, desc, o);
    app::checkRenderedImage(*run.image, allowBlack || tile.count > 0);  // a tile may be all sky
    const auto groups = app::reportSensors(run, a.scene, o, csvs, files);
    // The other views: a ray trace each, from the same solution.
    std::vector<app::RenderedView> more;
    for (size_t k = 1; k < views.size(); ++k) {
        more.push_back(app::renderView(run, views[k], o));
        app::checkRenderedImage(more.back().image, allowBlack);
    }
    run.report.begin("tone map + write");
    const std::string description = "rayrad rendering of " + a.scene;
    if (tile.count > 0) {
        for (const auto& path : viewImages.front())
            files.set(path, app::encodeTile(path, *run.image, tile, description + (views.size() > 1 ? ", view " + views.front() : "")));
    } else {
        app::stageImages(viewImages.front(), *run.image, run.displayImage ? *run.displayImage : *run.image, display,
                         description + (views.size() > 1 ? ", view " + views.front() : ""), files);
    }
    for (size_t k = 1; k < views.size(); ++k)
        app::stageImages(viewImages[k], more[k - 1].image, more[k - 1].displayImage, display, description + ", view " + views[k],
                         files);
    app::stageReports(run, a.scene, reports, groups ? &*groups : nullptr, files);
    files.commit();
    run.report.end();
    for (const auto& paths : viewImages) app::reportWritten(paths);
    app::reportWritten(others);
    app::printSolveSummary(run);
    std::cerr << app::stagesSummary(run) << run.report.toString();
    return 0;
}

/// rayrad export: solve (or read a saved solution) and write the lit mesh as .glb.
int runExport(const CommonArgs& a, const std::string& output, const std::string& solution, const std::string& exposure,
              tonemap::DisplayOptions display) {
    display = tonemap::parseExposure(exposure, display);
    if (lowerExtension(output) != ".glb")
        throw InputError(placeMessage(output, "-o", "the lit mesh is written as binary glTF: give a .glb file"));
    app::PipelineOptions o;
    o.overrides = overridesOf(a);
    o.quiet = a.quiet;
    o.wantSensors = false;
    o.solutionFile = solution;
    const auto desc = scene::loadScene(a.scene, o.overrides);
    OutputFiles files = app::filesOf(desc);
    if (!solution.empty()) files.addInput(solution);
    files.add(output);
    auto run = app::runPipeline(a.scene, desc, o);
    run.report.begin("export lit mesh");
    // Exposed for what the scene's camera sees (as a rendering of it would be), else for
    // the whole solution.
    const double adaptation = run.scene.camera ? app::viewsAdaptationLuminance(run, {*run.scene.camera}, o)
                                               : app::solutionAdaptationLuminance(run);
    files.set(output, app::exportLitMesh(run, display, adaptation, a.scene));
    files.commit();
    run.report.end();
    app::reportWritten({output});
    app::printSolveSummary(run);
    std::cerr << app::stagesSummary(run) << run.report.toString();
    return 0;
}

int runInfo(const CommonArgs& a) { return app::printSceneInfo(a.scene, overridesOf(a)); }

}  // namespace

int main(int argc, char** argv) {
    // A file size limit (ulimit -f) then fails a write with EFBIG, which is reported,
    // instead of killing the process half-way through a file.
    std::signal(SIGXFSZ, SIG_IGN);
    CLI::App cli{"rayrad — physically based lighting simulation: progressive hierarchical radiosity for the\n"
                 "indirect light, a Whitted-style ray tracer for images, illuminance at sensors.\n"
                 "Units: metres, cd, lx, cd/m². Exit codes: 0 done, 1 internal error, 2 bad input (scene, options),\n"
                 "3 an output cannot be written (nothing is left half-written), 4 the result is not usable\n"
                 "(non-finite, all black; nothing written)."};
    cli.set_version_flag("--version", app::versionText(), "Print the version of rayrad and of its libraries");
    cli.require_subcommand(1);

    CommonArgs renderArgs, solveArgs, infoArgs;
    std::vector<std::string> outputs;
    std::string renderCsv, solveCsv, exposure = "auto", toneName = "exposure", whiteBalance = "none";
    std::optional<int> spp, seed;
    std::vector<std::string> cameras;
    std::string saveFile, solutionFile, tileText;
    std::vector<std::string> mergeOutputs, mergeTiles;
    int snapshots = 0;
    app::ReportArgs renderReports, solveReports;
    tonemap::DisplayOptions display;
    auto addReports = [](CLI::App* cmd, app::ReportArgs& r) {
        cmd->add_option("--convergence", r.convergence,
                        "Log error against time at every push-pull as CSV (seconds, shots, unshot % of the emitted flux, and the "
                        "indirect error at every sensor with a reference: vertex values always, the gather each "
                        "time the unshot energy has halved)");
        cmd->add_option("--report", r.report, "Write a JSON account of the run (stages, time, memory, sensors)");
        cmd->add_option("--grid-picture", r.gridPicture,
                        "Write the sensor grids' illuminance in false colour (.png/.jpg): isolux lines, legend, statistics");
    };

    auto* render = cli.add_subcommand("render", "Solve the lighting and render the scene's camera view");
    addCommon(render, renderArgs);
    render->add_option("-o,--output", outputs, "Output image(s): .exr (linear cd/m²), .png or .jpg (display)")->required();
    render->add_option("--sensors", renderCsv, "Also write the sensor table as CSV (sensors are gathered only when asked for)");
    render->add_option("--solution", solutionFile,
                       "Render from a solution saved by solve --save (no solve); refused if it was computed for other "
                       "geometry, materials, lights or settings");
    render->add_option("--tile", tileText,
                       "I/N: render only the I-th of N horizontal bands into an EXR tile; rayrad merge joins the tiles "
                       "(bit-identical to rendering the whole)");
    std::string framesText;
    render->add_option("--frames", framesText,
                       "all, K or A:B: render these frames (from 0) of the scene's \"camera_path\", images NAME.KKKK.EXT, "
                       "each written when done, all exposed alike (from the solution, not per frame)");
    render->add_option("--camera", cameras,
                       "The view(s) to render, by name (\"camera\", or a name in \"cameras\"), repeatable, or all; "
                       "several: one solve, a ray trace each, images NAME.VIEW.EXT (default: the first view)");
    render->add_option("--spp", spp, "Samples per pixel (default: render.spp, 4)")->check(CLI::Range(1, 65536));
    render->add_option("--seed", seed, "Random seed; the same seed gives the same image (default 1)")->check(CLI::Range(0, std::numeric_limits<int>::max()));
    render->add_option("--exposure", exposure, "\"auto\" (log-average luminance → 0.18) or stops: 2^stops per cd/m²")->default_str("auto");
    render->add_option("--tonemap", toneName,
                       "Tone operator: exposure, tumblin-rushmeier, ward or reinhard (docs/cli.md gives the equations)")
        ->default_str("exposure");
    render->add_option("--world-adaptation", display.tone.worldAdaptation,
                       "World adaptation luminance L_wa, cd/m² (default: the image's log-average)");
    render->add_option("--display-max", display.tone.displayMax, "The display's white L_dmax, cd/m² (sRGB's reference display: 80)")->default_str("80");
    render->add_option("--display-adaptation", display.tone.displayAdaptation,
                       "Display adaptation luminance L_da, cd/m² (tumblin-rushmeier; default L_dmax/2)");
    render->add_option("--max-contrast", display.tone.maxContrast, "The display's contrast C_max (tumblin-rushmeier)")
        ->default_str("100");
    render->add_option("--key", display.tone.key, "The key a (reinhard)")->default_str("0.18");
    render->add_option("--white", display.tone.white,
                       "The smallest luminance shown white, in key-scaled units (reinhard; default the image's largest)");
    render->add_option("--white-balance", whiteBalance,
                       "none, a colour temperature (3000K), grey-world or region:x,y,w,h: adapted to D65 (Bradford)")
        ->default_str("none");
    render->add_option("--ocio-config", display.ocioConfig, "OpenColorIO config file (default: rayrad's embedded sRGB config)");
    render->add_option("--display", display.display, "OCIO display (default: the config's default)");
    render->add_option("--view", display.view, "OCIO view (default: the display's default; the embedded config: Standard, \"ACES 1.0 SDR-video\", Raw)");
    render->add_option("--snapshots", snapshots,
                       "Also render K images during the solve (NAME.snap01.EXT ...), evenly spaced in log unshot energy")
        ->check(CLI::Range(0, 100));
    render->add_option("--false-colour", renderReports.falseColour,
                       "Also write the rendering's luminance in false colour (.png/.jpg; log scale, legend in cd/m²)");
    bool allowBlack = false;
    render->add_flag("--allow-black", allowBlack,
                     "Write the image even when every pixel is black (otherwise that is an error, exit 4)");
    addReports(render, renderReports);

    auto* solve = cli.add_subcommand("solve", "Solve the lighting and report illuminance at the sensors (no image)");
    addCommon(solve, solveArgs);
    solve->add_option("--sensors", solveCsv, "Write the sensor table as CSV");
    solve->add_option("--save", saveFile,
                      "Write the solution (FILE.rrs): render --solution FILE.rrs then renders any view without solving");
    addReports(solve, solveReports);

    CommonArgs exportArgs;
    std::string exportOutput, exportSolution, exportExposure = "auto", exportTone = "exposure", exportWhite = "none";
    auto* exporter = cli.add_subcommand("export", "Write the lit mesh as binary glTF (.glb) for walkthroughs: light baked into "
                                                  "vertex colours, an unlit material, absolute luminance kept in _LUMINANCE");
    addCommon(exporter, exportArgs);
    exporter->add_option("-o,--output", exportOutput, "The .glb file")->required();
    exporter->add_option("--solution", exportSolution, "Use a solution saved by solve --save (no solve)");
    exporter->add_option("--exposure", exportExposure,
                         "\"auto\" (the log-average luminance of the scene camera's view, else of the solution → 0.18) or stops: "
                         "2^stops per cd/m²")
        ->default_str("auto");
    exporter->add_option("--tonemap", exportTone, "Tone operator: exposure, tumblin-rushmeier, ward or reinhard")
        ->default_str("exposure");
    exporter->add_option("--white-balance", exportWhite, "none, a colour temperature (3000K) or grey-world")->default_str("none");

    app::SweepOptions sweepOptions;
    auto* sweep = cli.add_subcommand("sweep", "Expand a grid of scene values into independent jobs (one rayrad command line "
                                              "each) for GNU parallel or a Slurm job array");
    sweep->add_option("scene", sweepOptions.scene, "Scene file")->required();
    sweep->add_option("--vary", sweepOptions.vary, "KEY=V1,V2,...: a --set key and the values it takes (repeatable; "
                                                   "every combination is a job)")->required();
    sweep->add_option("--run", sweepOptions.command,
                      "The rayrad subcommand and options of every job; {job} becomes the job's number, e.g. "
                      "\"solve --sensors out/{job}.csv\"")->default_str("solve");
    sweep->add_option("--jobs", sweepOptions.jobsFile, "The jobs file to write (a .csv of each job's values beside it)")->required();
    sweep->add_option("--rayrad", sweepOptions.rayrad, "The rayrad the jobs run (default: this one's absolute path)");

    auto* info = cli.add_subcommand("info", "Counts, and the stages the scene needs; for an .ies or .ldt file, its photometry");
    addCommon(info, infoArgs);

    auto* merge = cli.add_subcommand("merge", "Join the tiles of one rendering (render --tile I/N) into the whole image");
    merge->add_option("-o,--output", mergeOutputs, "Output image(s): .exr (bit-identical to rendering the whole), .png, .jpg")
        ->required()
        ->allow_extra_args(false);  // -o takes one file; the rest are tiles
    merge->add_option("tiles", mergeTiles, "The tile EXR files, all N of them, in any order")->required();

    app::CompareOptions compareOptions;
    auto* compare = cli.add_subcommand("compare", "Compare an image (a rendering) against a reference (a photograph or "
                                                  "another rendering) in luminance; exit 1 when a --fail-above bound is exceeded");
    compare->add_option("a", compareOptions.a, "The image under test (EXR, PNG, JPEG); calibrated onto the reference")->required();
    compare->add_option("b", compareOptions.b, "The reference image")->required();
    compare->add_option("--a-space", compareOptions.aSpace, "linear, srgb or auto (EXR linear, PNG/JPEG sRGB)")->default_str("auto");
    compare->add_option("--b-space", compareOptions.bSpace, "as --a-space, for the reference")->default_str("auto");
    compare->add_option("--align", compareOptions.alignFile,
                        "JSON file of 4 or more corresponding points [{\"a\": [x, y], \"b\": [x, y]}] (pixels from the "
                        "top-left): a is resampled onto b's grid through their homography");
    compare->add_option("--regions", compareOptions.regionsFile,
                        "JSON file of named regions [{\"name\", \"x\", \"y\", \"width\", \"height\"}] with their own figures");
    compare->add_option("--calibrate", compareOptions.calibrate,
                        "none, exposure (one least-squares factor) or channels (one per channel: exposure and white balance)")
        ->default_str("exposure");
    compare->add_option("--diff-map", compareOptions.diffMap, "Write |relative luminance difference| in false colour (.png/.jpg)");
    compare->add_option("--side-by-side", compareOptions.sideBySide, "Write the calibrated image and the reference side by side");
    compare->add_option("--report", compareOptions.report, "Write the figures as JSON");
    compare->add_option("--csv", compareOptions.csv, "Write the figures as CSV, one row per region");
    compare->add_option("--fail-above", compareOptions.failAbove,
                        "METRIC=VALUE, repeatable: exit 1 when the whole image's figure exceeds it (mean_abs_rel_pct, "
                        "median_abs_rel_pct, p95_abs_rel_pct, abs_mean_rel_pct, rms_log, ssim_loss = 1 − SSIM, mean_delta_e2000, "
                        "p95_delta_e2000, mean_flip)");

    app::ValidateOptions validateOptions;
    validateOptions.scene = app::bundledPath(validateOptions.scene);
    auto* validate = cli.add_subcommand("validate", "Reproduce a validation from the paper on this machine");
    auto* validateCube = validate->add_subcommand(
        "cube", "The empty cube: mesh sweep and cluster sweep (paper Tables 2-3), ablations, error-vs-time plots");
    app::ValidateSphereOptions sphereOptions;
    sphereOptions.sceneDir = app::bundledPath(sphereOptions.sceneDir);
    auto* validateSphere = validate->add_subcommand(
        "sphere", "The sphere with mirrors: SPH2 and SPH4, 768 and 12 288 triangles, clusters on and off (paper Table 4)");
    validateSphere->add_flag("--quick", sphereOptions.quick, "The 768-triangle sphere only (seconds)");
    validateSphere->add_option("--scenes", sphereOptions.sceneDir, "Directory with sph2.json and sph4.json")
        ->default_str(sphereOptions.sceneDir);
    validateSphere->add_option("--out", sphereOptions.outDir, "Output directory")->default_str(sphereOptions.outDir);
    validateSphere->add_option("--threads", sphereOptions.threads, "Worker threads per run (default: all cores)")
        ->check(CLI::Range(0, kMaxThreads));
    app::ValidateLuminaireOptions luminaireOptions;
    luminaireOptions.dataDir = app::bundledPath(luminaireOptions.dataDir);
    auto* validateLuminaire = validate->add_subcommand(
        "luminaire", "Every bundled photometric file: direct light from its table, a closed sphere's indirect light");
    validateLuminaire->add_option("--data", luminaireOptions.dataDir, "Directory with .ies and .ldt files")
        ->default_str(luminaireOptions.dataDir);
    validateLuminaire->add_option("--out", luminaireOptions.outDir, "Output directory")->default_str(luminaireOptions.outDir);
    validate->require_subcommand(1);
    validateCube->add_flag("--quick", validateOptions.quick, "A subset at 1 200 and 4 800 triangles (about a minute)");
    validateCube->add_option("--scene", validateOptions.scene, "The cube scene")->default_str(validateOptions.scene);
    validateCube->add_option("--out", validateOptions.outDir, "Output directory")->default_str(validateOptions.outDir);
    validateCube->add_option("--threads", validateOptions.threads, "Worker threads per run (default: all cores)")
        ->check(CLI::Range(0, kMaxThreads));

    try {
        cli.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        if (e.get_exit_code() == 0) return cli.exit(e);  // --help, --version
        // One line, as for every other error.
        std::cerr << "rayrad: " << e.what() << " (--help lists the options)\n";
        return kExitInputError;
    }

    try {
        if (compare->parsed()) return app::compareImages(compareOptions);
        if (merge->parsed()) return app::mergeTiles(mergeOutputs, mergeTiles);
        if (sweep->parsed()) return app::writeSweep(sweepOptions);
        if (validateSphere->parsed()) return app::validateSphere(sphereOptions);
        if (validateLuminaire->parsed()) return app::validateLuminaire(luminaireOptions);
        if (validate->parsed()) return app::validateCube(validateOptions);
        CommonArgs& common = render->parsed() ? renderArgs : solve->parsed() ? solveArgs : exporter->parsed() ? exportArgs : infoArgs;
        std::unique_ptr<tbb::global_control> threads;
        if (common.threads > 0)
            threads = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, common.threads);
        if (render->parsed()) {
            display.tone.op = tonemap::parseToneOperator(toneName);
            tonemap::checkToneOptions(display.tone);
            if (exposure != "auto" && display.tone.op != tonemap::ToneOperator::Exposure)
                throw InputError(placeMessage("", "--exposure", "sets the exposure operator's scale; --tonemap " + toneName +
                                                                    " chooses its own (give --tonemap exposure)"));
            display.whiteBalance = tonemap::parseWhiteBalance(whiteBalance);
        }
        if (render->parsed())
            return runRender(renderArgs, outputs, renderCsv, spp, seed, exposure, display, snapshots, allowBlack,
                             renderReports, cameras, solutionFile, tileText, framesText);
        if (solve->parsed()) return runSolve(solveArgs, solveCsv, solveReports, saveFile);
        if (exporter->parsed()) {
            tonemap::DisplayOptions exportDisplay;
            exportDisplay.tone.op = tonemap::parseToneOperator(exportTone);
            if (exportExposure != "auto" && exportDisplay.tone.op != tonemap::ToneOperator::Exposure)
                throw InputError(placeMessage("", "--exposure", "sets the exposure operator's scale: give --tonemap exposure"));
            exportDisplay.whiteBalance = tonemap::parseWhiteBalance(exportWhite);
            if (exportDisplay.whiteBalance.kind == tonemap::WhiteBalance::Kind::Region)
                throw InputError(placeMessage("", "--white-balance", "a region is of an image: export takes none, a temperature or grey-world"));
            return runExport(exportArgs, exportOutput, exportSolution, exportExposure, exportDisplay);
        }
        return runInfo(infoArgs);
    } catch (const InputError& e) {
        std::cerr << "rayrad: " << e.what() << "\n";
        return kExitInputError;
    } catch (const OutputError& e) {
        std::cerr << "rayrad: " << e.what() << "\n";
        return kExitOutputError;
    } catch (const ResultError& e) {
        std::cerr << "rayrad: " << e.what() << "\n";
        return kExitResultError;
    } catch (const std::bad_alloc&) {
        std::cerr << "rayrad: out of memory (run `rayrad info` for the expected peak memory)\n";
        return kExitInternalError;
    } catch (const std::exception& e) {
        std::cerr << "rayrad: internal error: " << e.what() << "\n";
        return kExitInternalError;
    }
}
