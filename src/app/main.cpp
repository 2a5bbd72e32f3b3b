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
#include <radiosity/solution_file.h>
#include <app/validate_sphere.h>
#include <app/sensor_table.h>
#include <core/input_error.h>
#include <core/output_file.h>
#include <core/result_error.h>
#include <radiosity/direct_light.h>
#include <radiosity/shooting_solver.h>
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
constexpr double kMaxExposureStops = 64;
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

void printSolveSummary(const app::PipelineRun& run) {
    const auto& s = run.solution;
    auto balance = radiosity::energyBalance(run.scene, run.mesh, s, run.lights->emittedFlux());
    fmt::print(stderr, "patches: {}, channels: {}, shots: {}, unshot: {:.4g}% of {:.6g} lm ({})\n",
               run.mesh.patches.size(), run.singleChannel ? "1 (grey scene)" : "3", s.shots,
               s.initialUnshotFlux > 0 ? 100 * s.remainingUnshotFlux / s.initialUnshotFlux : 0.0, s.initialUnshotFlux,
               s.converged ? "converged" : "NOT converged: " + run.shooting.stopReason);
    if (run.shooting.overshootStalled)
        fmt::print(stderr, "note: overshooting was switched off during the solve: the residual stalled with it\n");
    fmt::print(stderr, "{}\n", run.clustering.statistics());
    if (run.edgeVertices > 0) fmt::print(stderr, "seam vertices (concave edges and corners) from a point gather: {}\n", run.edgeVertices);
    if (run.sensorGathers > 0)
        fmt::print(stderr, "sensor gathers: {} for {} sensors (corner and midpoint re-gathers near edges)\n",
                   run.sensorGathers, run.sensors.size());
    if (run.clustering.enabled) {
        const auto& t = run.shooting;
        const std::string throughImages =
            t.imageTransfers > 0 ? fmt::format(" ({} from mirror images, {:.1f} % of those carrying light)", t.imageTransfers,
                                               100.0 * static_cast<double>(t.imageTransfersLit) / t.imageTransfers)
                                 : "";
        fmt::print(stderr, "transfers: {} cluster→cluster{}, {} patch→patch pairs, {} corrections, {} push-pulls; ΔI_max {:.4g} lx\n",
                   t.clusterTransfers, throughImages, t.patchPairs, t.corrections, t.pushPulls, run.maxIlluminanceStep);
    }
    std::string alsoAbsorbed;
    if (!run.scene.mirrors.empty() && run.scene.solver.mirrorImages)
        alsoAbsorbed += fmt::format(" + {:.6g} lm by mirrors", balance.mirrorAbsorbed);
    if (balance.backAbsorbed > 0)
        alsoAbsorbed += fmt::format(" + {:.6g} lm on backs of one-sided surfaces", balance.backAbsorbed);
    fmt::print(stderr, "energy: emitted {:.6g} lm, absorbed {:.6g} lm{}, unshot {:.6g} lm, not accounted {:+.4f}% "
                       "(direct pass {:+.4f}%, secondary pass {:+.4f}%)\n",
               balance.emitted, balance.absorbed, alsoAbsorbed.empty() ? "" : " (" + alsoAbsorbed.substr(3) + ")",
               balance.unshot, 100 * balance.relativeError(),
               100 * balance.directError(), 100 * balance.secondaryError());
    const auto& st = run.shooting;
    fmt::print(stderr, "closure: {:.3g}% of reflected light escapes; per-shot energy conservation {}{}; overshooting {}\n",
               100 * st.escapeFraction,
               st.conserving ? "on" : "off (" + st.conservationOff + ")",
               st.conserving ? fmt::format(" (largest adjustment {:.3g}%, {} shots beyond the {:.0f}% bound left alone)",
                                           100 * st.largestRescale, st.unbalancedShots, 100 * radiosity::kConservationBound)
                             : "",
               st.overshooting ? "on" : "off");
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
    auto run = app::runPipeline(a.scene, o);
    if (!save.empty())
        files.set(save, radiosity::encodeSolution(run.solution, radiosity::fingerprintOf(run.scene, run.mesh),
                                                  run.mesh.vertices.size()));
    const auto groups = app::reportSensors(run, a.scene, o, csvs, files);
    app::stageReports(run, a.scene, reports, groups ? &*groups : nullptr, files);
    files.commit();
    outputs.push_back(save);
    app::reportWritten(outputs);
    printSolveSummary(run);
    std::cerr << app::stagesSummary(run) << run.report.toString();
    return 0;
}

/// --exposure: "auto" or a finite number of stops within ±64 (2^64 ≈ 1.8e19 per cd/m²).
tonemap::DisplayOptions parseExposure(const std::string& exposure, tonemap::DisplayOptions display) {
    if (exposure == "auto") return display;
    double stops = 0;
    try {
        size_t used = 0;
        stops = std::stod(exposure, &used);
        if (used != exposure.size()) throw std::invalid_argument("trailing");
    } catch (const std::exception&) {
        throw InputError(placeMessage("", "--exposure", "expected \"auto\" or a number of stops, got \"" + exposure + "\""));
    }
    if (!(std::abs(stops) <= kMaxExposureStops))
        throw InputError(placeMessage("", "--exposure", fmt::format("expected stops between -{0} and {0}, got {1}: "
                                                                    "that would make every pixel black or white",
                                                                    kMaxExposureStops, exposure)));
    display.exposureStops = stops;
    display.autoExposure = false;
    return display;
}

int runRender(const CommonArgs& a, const std::vector<std::string>& images, const std::string& csv,
              std::optional<int> spp, std::optional<int> seed, const std::string& exposure,
              const tonemap::DisplayOptions& displayIn, int snapshots, bool allowBlack, const app::ReportArgs& reports,
              const std::vector<std::string>& cameras, const std::string& solution, const std::string& tileText) {
    const tonemap::DisplayOptions display = parseExposure(exposure, displayIn);
    tonemap::checkDisplayOptions(display);
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
    auto run = app::runPipeline(a.scene, o);
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
    printSolveSummary(run);
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
                        "Log error against time at every push-pull as CSV (seconds, shots, unshot %, and the "
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
    render->add_option("--view", display.view, "OCIO view (default: the display's default)");
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
                        "p95_delta_e2000)");

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
        if (validateSphere->parsed()) return app::validateSphere(sphereOptions);
        if (validateLuminaire->parsed()) return app::validateLuminaire(luminaireOptions);
        if (validate->parsed()) return app::validateCube(validateOptions);
        CommonArgs& common = render->parsed() ? renderArgs : solve->parsed() ? solveArgs : infoArgs;
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
                             renderReports, cameras, solutionFile, tileText);
        if (solve->parsed()) return runSolve(solveArgs, solveCsv, solveReports, saveFile);
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
