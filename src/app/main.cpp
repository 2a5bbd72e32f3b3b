// rayrad: parse, build, solve, render, write — one call per stage (see app/pipeline.h).
#include <app/annual/annual_command.h>
#include <app/command_line.h>
#include <app/compare.h>
#include <app/image_output.h>
#include <app/lit_mesh_export.h>
#include <app/pipeline.h>
#include <app/result_checks.h>
#include <app/run_outputs.h>
#include <app/scene_info.h>
#include <app/sensor_table.h>
#include <app/solve_summary.h>
#include <app/sweep.h>
#include <app/tiles.h>
#include <app/validate_cube.h>
#include <app/validate_daylight.h>
#include <app/validate_glare.h>
#include <app/validate_luminaire.h>
#include <app/validate_runs.h>
#include <app/validate_sphere.h>
#include <app/version.h>
#include <app/views.h>
#include <app/walkthrough.h>
#include <core/input_error.h>
#include <core/output_file.h>
#include <core/termination.h>
#include <core/result_error.h>
#include <core/text.h>
#include <radiosity/radiosity.h>
#include <tonemap/display_transform.h>
#include <tonemap/image_io.h>

#include <fmt/format.h>
#include <tbb/global_control.h>
#include <CLI/CLI.hpp>

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <iostream>
#include <limits>
#include <memory>

using namespace rayrad;

namespace {

// Exit codes (docs/cli.md): 0 done, 1 internal error, 2 bad input (scene, options),
// 3 an output cannot be written, 4 the result is not usable (non-finite, all black).
constexpr int kExitInternalError = 1;
constexpr int kExitInputError = 2;
constexpr int kExitOutputError = 3;
constexpr int kExitResultError = 4;

std::vector<scene::Override> overridesOf(const app::CommonArgs& a) {
    std::vector<scene::Override> out;
    for (const auto& s : a.sets) out.push_back(scene::parseOverride(s));
    return out;
}

int runSolve(const app::SolveArgs& args) {
    const app::CommonArgs& a = args.common;
    const std::string &csv = args.csv, &save = args.save;
    const app::ReportArgs& reports = args.reports;
    app::PipelineOptions o;
    o.overrides = overridesOf(a);
    o.quiet = a.quiet;
    o.logConvergence = !reports.convergence.empty();
    o.observerFisheyes = !reports.glarePictures.empty();
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
        files.set(save,
                  radiosity::encodeSolution(run.lighting.solution, radiosity::fingerprintOf(run.scene, run.mesh),
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
int runFrames(const app::CommonArgs& a, app::PipelineOptions o, const std::vector<std::string>& images,
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
        app::stageImages(paths, view.image, view.displayImage, steady,
                         fmt::format("rayrad rendering of {}, frame {}", a.scene, k), files);
        files.commit();
        if (!a.quiet) app::reportWritten(paths);
    }
    app::printSolveSummary(run);
    std::cerr << app::stagesSummary(run) << run.report.toString();
    return 0;
}

/// The display options of render: tone operator, exposure, white balance, checked.
tonemap::DisplayOptions renderDisplay(const app::RenderArgs& args) {
    tonemap::DisplayOptions display = args.display;
    display.tone.op = tonemap::parseToneOperator(args.tone);
    tonemap::checkToneOptions(display.tone);
    if (args.exposure != "auto" && display.tone.op != tonemap::ToneOperator::Exposure)
        throw InputError(placeMessage("", "--exposure",
                                      "sets the exposure operator's scale; --tonemap " + args.tone +
                                          " chooses its own (give --tonemap exposure)"));
    display.whiteBalance = tonemap::parseWhiteBalance(args.whiteBalance);
    display = tonemap::parseExposure(args.exposure, display);
    if (const auto warning = tonemap::checkDisplayOptions(display)) fmt::print(stderr, "warning: {}\n", *warning);
    return display;
}

/// Options that cannot go together with --tile, --snapshots or --frames.
void checkRenderOptions(const app::RenderArgs& args, const app::Tile& tile, const app::PipelineOptions& o) {
    if (tile.count > 0) {
        for (const auto& path : args.outputs)
            if (!tonemap::isHdrFormat(path))
                throw InputError(
                    placeMessage(path, "--tile", "a tile is written as EXR (rayrad merge makes the PNG or JPEG)"));
        if (args.snapshots > 0)
            throw InputError(placeMessage("", "--tile", "snapshots are of whole images: render them without --tile"));
        if (!args.reports.falseColour.empty())
            throw InputError(placeMessage("", "--tile", "a false-colour picture is of the whole image"));
    }
    if (!args.solution.empty() && args.snapshots > 0)
        throw InputError(
            placeMessage("", "--snapshots", "a saved solution (--solution) has no solve to take snapshots of"));
    if (args.frames.empty()) return;
    const std::vector<std::pair<bool, const char*>> alone = {
        {!args.cameras.empty(), "--camera"},
        {tile.count > 0, "--tile"},
        {args.snapshots > 0, "--snapshots"},
        {!args.reports.falseColour.empty(), "--false-colour"},
        {o.wantSensors || o.logConvergence, "--sensors, --report, --grid-picture, --glare-pictures or --convergence"}};
    for (const auto& [given, option] : alone)
        if (given)
            throw InputError(placeMessage("", "--frames",
                                          std::string("renders the camera path's frames alone: not with ") + option));
}

/// Every file a render writes, checked before the work: per view its images, the
/// snapshots, the sensor tables and reports (`others`).
struct RenderOutputs {
    std::vector<std::string> views;
    std::vector<std::vector<std::string>> viewImages;  ///< per view, its output paths
    app::SensorFiles csvs;
    std::vector<std::string> others;
};

RenderOutputs renderOutputs(const app::RenderArgs& args, const scene::SceneDesc& desc,
                            const tonemap::DisplayOptions& display, const app::Tile& tile, app::PipelineOptions& o,
                            OutputFiles& files) {
    RenderOutputs out;
    out.views = app::selectViews(desc, args.cameras);
    o.view = out.views.front();
    if (tile.count > 0 && out.views.size() > 1)
        throw InputError(placeMessage("", "--tile", "tiles are of one view: give one --camera"));
    for (const auto& [name, c] : desc.views)
        if (name == o.view) std::tie(o.rowBegin, o.rowEnd) = app::tileRows(tile, c.height);
    for (const auto& v : out.views) {
        std::vector<std::string> paths;
        for (const auto& path : args.outputs) paths.push_back(app::viewPath(path, v, out.views.size()));
        out.viewImages.push_back(paths);
        for (const auto& [name, c] : desc.views)
            if (name == v) tonemap::checkWhiteBalance(display.whiteBalance, c.width, c.height);
    }
    o.snapshotOutputs = out.viewImages.front();
    if (!args.solution.empty()) files.addInput(args.solution);
    for (const auto& paths : out.viewImages) app::addImageOutputs(paths, files);
    for (int k = 1; k <= args.snapshots; ++k)
        for (const auto& path : out.viewImages.front()) files.add(app::snapshotPath(path, k));
    out.csvs = app::sensorFiles(desc, args.csv);
    out.others = app::addSensorAndReportOutputs(desc, out.csvs, args.reports, files);
    return out;
}

int runRender(const app::RenderArgs& args) {
    const app::CommonArgs& a = args.common;
    const tonemap::DisplayOptions display = renderDisplay(args);
    app::PipelineOptions o;
    o.overrides = overridesOf(a);
    if (args.spp) o.overrides.push_back({"render.spp", std::to_string(*args.spp)});
    if (args.seed) o.overrides.push_back({"render.seed", std::to_string(*args.seed)});
    o.quiet = a.quiet;
    o.wantImage = true;
    // Sensors only when something reports them.
    o.wantSensors = !args.csv.empty() || !args.reports.report.empty() || !args.reports.gridPicture.empty() ||
                    !args.reports.glarePictures.empty();
    o.observerFisheyes = !args.reports.glarePictures.empty();
    o.logConvergence = !args.reports.convergence.empty();
    o.snapshots = args.snapshots;
    o.display = display;
    o.solutionFile = args.solution;
    const app::Tile tile = args.tile.empty() ? app::Tile{} : app::parseTile(args.tile);
    checkRenderOptions(args, tile, o);
    if (!args.frames.empty()) return runFrames(a, o, args.outputs, args.frames, display, args.allowBlack);
    // Read and check the scene, then every output, before any work.
    const auto desc = scene::loadScene(a.scene, o.overrides);
    OutputFiles files = app::filesOf(desc);
    const RenderOutputs outputs = renderOutputs(args, desc, display, tile, o, files);
    const auto& views = outputs.views;
    if (tile.count > 0)
        for (const auto& [name, camera] : desc.views)
            if (name == views.front() && tile.count > camera.height)
                throw InputError(placeMessage("", "--tile", fmt::format("{} bands of an image {} pixels high: at most "
                                                                        "{} (a band is at least a row)",
                                                                        tile.count, camera.height, camera.height)));
    o.files = &files;
    auto run = app::runPipeline(a.scene, desc, o);
    app::checkRenderedImage(*run.image, args.allowBlack || tile.count > 0);  // a tile may be all sky
    const auto groups = app::reportSensors(run, a.scene, o, outputs.csvs, files);
    // The other views: a ray trace each, from the same solution.
    std::vector<app::RenderedView> more;
    for (size_t k = 1; k < views.size(); ++k) {
        more.push_back(app::renderView(run, views[k], o));
        app::checkRenderedImage(more.back().image, args.allowBlack);
    }
    run.report.begin("tone map + write");
    const std::string description = "rayrad rendering of " + a.scene;
    const std::string firstView = description + (views.size() > 1 ? ", view " + views.front() : "");
    if (tile.count > 0) {
        for (const auto& path : outputs.viewImages.front())
            files.set(path, app::encodeTile(path, *run.image, tile, firstView, app::renderFingerprint(run)));
    } else {
        app::stageImages(outputs.viewImages.front(), *run.image, run.displayImage ? *run.displayImage : *run.image,
                         display, firstView, files);
    }
    for (size_t k = 1; k < views.size(); ++k)
        app::stageImages(outputs.viewImages[k], more[k - 1].image, more[k - 1].displayImage, display,
                         description + ", view " + views[k], files);
    app::stageReports(run, a.scene, args.reports, groups ? &*groups : nullptr, files);
    files.commit();
    run.report.end();
    for (const auto& paths : outputs.viewImages) app::reportWritten(paths);
    app::reportWritten(outputs.others);
    app::printSolveSummary(run);
    std::cerr << app::stagesSummary(run) << run.report.toString();
    return 0;
}

/// rayrad export: solve (or read a saved solution) and write the lit mesh as .glb.
int runExport(const app::ExportArgs& args) {
    const app::CommonArgs& a = args.common;
    const std::string &output = args.output, &solution = args.solution;
    tonemap::DisplayOptions display;
    display.tone.op = tonemap::parseToneOperator(args.tone);
    if (args.exposure != "auto" && display.tone.op != tonemap::ToneOperator::Exposure)
        throw InputError(placeMessage("", "--exposure", "sets the exposure operator's scale: give --tonemap exposure"));
    display.whiteBalance = tonemap::parseWhiteBalance(args.whiteBalance);
    if (display.whiteBalance.kind == tonemap::WhiteBalance::Kind::Region)
        throw InputError(placeMessage("", "--white-balance",
                                      "a region is of an image: export takes none, a temperature or grey-world"));
    display = tonemap::parseExposure(args.exposure, display);
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

/// The chosen subcommand, run.
int runCommand(const app::CommandLine& args) {
    using Command = app::CommandLine::Command;
    switch (args.command) {
        case Command::Compare:
            return app::compareImages(args.compare);
        case Command::Glare:
            return app::runGlare(args.glare);
        case Command::Merge:
            return app::mergeTiles(args.merge.outputs, args.merge.tiles);
        case Command::Sweep:
            return app::writeSweep(args.sweep);
        case Command::ValidateSphere:
            return app::validateSphere(args.validateSphere);
        case Command::ValidateLuminaire:
            return app::validateLuminaire(args.validateLuminaire);
        case Command::ValidateDaylight:
            return app::validateDaylight();
        case Command::ValidateGlare:
            return app::validateGlare();
        case Command::ValidateCube:
            return app::validateCube(args.validateCube);
        case Command::Render:
            return runRender(args.render);
        case Command::Solve:
            return runSolve(args.solve);
        case Command::Annual:
            return app::runAnnual(args.annual);
        case Command::Export:
            return runExport(args.exporter);
        case Command::Info:
            return app::printSceneInfo(args.info, overridesOf(args.info.common));
    }
    return kExitInternalError;
}

}  // namespace

int main(int argc, char** argv) {
    // A file size limit (ulimit -f) then fails a write with EFBIG, which is reported,
    // instead of killing the process half-way through a file.
    std::signal(SIGXFSZ, SIG_IGN);
    // A reader that closed its end of the pipe (`rayrad solve … | head -1`): the write to
    // standard output fails, and that is reported (below) instead of killing the process.
    std::signal(SIGPIPE, SIG_IGN);
    // SIGTERM (a batch system's time limit), SIGINT, SIGHUP: temporaries removed, old
    // outputs left as they were.
    installTerminationCleanup();
    CLI::App cli{
        "rayrad — physically based lighting simulation: progressive hierarchical radiosity for the\n"
        "indirect light, a Whitted-style ray tracer for images, illuminance at sensors.\n"
        "Units: metres, cd, lx, cd/m². Exit codes: 0 done, 1 internal error, 2 bad input (scene, options),\n"
        "3 an output cannot be written (nothing is left half-written), 4 the result is not usable\n"
        "(non-finite, all black; nothing written)."};
    cli.set_version_flag("--version", app::versionText(), "Print the version of rayrad and of its libraries");
    cli.require_subcommand(1);
    app::CommandLine args;
    app::defineCommandLine(cli, args);
    try {
        cli.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        if (e.get_exit_code() == 0) return cli.exit(e);  // --help, --version
        // One line, as for every other error.
        std::cerr << "rayrad: " << e.what() << " (--help lists the options)\n";
        return kExitInputError;
    }
    app::noteChosenCommand(cli, args);

    try {
        std::unique_ptr<tbb::global_control> threads;
        if (const app::CommonArgs* common = args.common(); common && common->threads > 0)
            threads =
                std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, common->threads);
        const int code = runCommand(args);
        std::cout.flush();
        if (!std::cout && code == 0) {
            std::cerr << "rayrad: standard output: cannot write (the reading end of the pipe was closed?); "
                         "what it did not take is lost\n";
            return kExitOutputError;
        }
        return code;
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
