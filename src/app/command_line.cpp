#include <app/command_line.h>

#include <app/validate_runs.h>

#include <CLI/CLI.hpp>

#include <limits>

namespace rayrad::app {

namespace {

void addCommon(CLI::App* cmd, CommonArgs& a) {
    cmd->add_option("scene", a.scene, "Scene file (JSON, see docs/scene-format.md); - reads it from standard input")
        ->required();
    cmd->add_option("--set", a.sets, "Override a scene value, e.g. --set radiosity.max_edge=0.25 (repeatable)");
    cmd->add_option("--threads", a.threads, "Worker threads (default 0: all cores)")->check(CLI::Range(0, kMaxThreads));
    cmd->add_flag("-q,--quiet", a.quiet, "No progress line");
}

void addReports(CLI::App* cmd, ReportArgs& r) {
    cmd->add_option(
        "--convergence", r.convergence,
        "Log error against time at every push-pull as CSV (seconds, shots, unshot % of the emitted flux, and the "
        "indirect error at every sensor with a reference: vertex values always, the gather each "
        "time the unshot energy has halved)");
    cmd->add_option("--report", r.report, "Write a JSON account of the run (stages, time, memory, sensors)");
    cmd->add_option(
        "--grid-picture", r.gridPicture,
        "Write the sensor grids' illuminance in false colour (.png/.jpg): isolux lines, legend, statistics");
    cmd->add_option("--glare-pictures", r.glarePictures,
                    "Write each observer's 180° fisheye with its glare sources marked, DIR/NAME.png (the observers then "
                    "get DGP also without a daylight)");
}

void addRender(CLI::App& cli, RenderArgs& a) {
    auto* render = cli.add_subcommand("render", "Solve the lighting and render the scene's camera view");
    addCommon(render, a.common);
    render->add_option("-o,--output", a.outputs, "Output image(s): .exr (linear cd/m²), .png or .jpg (display)")
        ->required();
    render->add_option("--sensors", a.csv,
                       "Also write the sensor table as CSV (sensors are gathered only when asked for)");
    render->add_option("--solution", a.solution,
                       "Render from a solution saved by solve --save (no solve); refused if it was computed for other "
                       "geometry, materials, lights or settings");
    render->add_option("--tile", a.tile,
                       "I/N: render only the I-th of N horizontal bands into an EXR tile; rayrad merge joins the tiles "
                       "(bit-identical to rendering the whole)");
    render->add_option(
        "--frames", a.frames,
        "all, K or A:B: render these frames (from 0) of the scene's \"camera_path\", images NAME.KKKK.EXT, "
        "each written when done, all exposed alike (from the solution, not per frame)");
    render->add_option("--camera", a.cameras,
                       "The view(s) to render, by name (\"camera\", or a name in \"cameras\"), repeatable, or all; "
                       "several: one solve, a ray trace each, images NAME.VIEW.EXT (default: the first view)");
    render->add_option("--spp", a.spp, "Samples per pixel (default: render.spp, 4)")->check(CLI::Range(1, 65536));
    render->add_option("--seed", a.seed, "Random seed; the same seed gives the same image (default 1)")
        ->check(CLI::Range(0, std::numeric_limits<int>::max()));
    render->add_option("--exposure", a.exposure, "\"auto\" (log-average luminance → 0.18) or stops: 2^stops per cd/m²")
        ->default_str("auto");
    render
        ->add_option("--tonemap", a.tone,
                     "Tone operator: exposure, tumblin-rushmeier, ward or reinhard (docs/cli.md gives the equations)")
        ->default_str("exposure");
    render->add_option("--world-adaptation", a.display.tone.worldAdaptation,
                       "World adaptation luminance L_wa, cd/m² (default: the image's log-average)");
    render
        ->add_option("--display-max", a.display.tone.displayMax,
                     "The display's white L_dmax, cd/m² (sRGB's reference display: 80)")
        ->default_str("80");
    render->add_option("--display-adaptation", a.display.tone.displayAdaptation,
                       "Display adaptation luminance L_da, cd/m² (tumblin-rushmeier; default L_dmax/2)");
    render->add_option("--max-contrast", a.display.tone.maxContrast, "The display's contrast C_max (tumblin-rushmeier)")
        ->default_str("100");
    render->add_option("--key", a.display.tone.key, "The key a (reinhard)")->default_str("0.18");
    render->add_option(
        "--white", a.display.tone.white,
        "The smallest luminance shown white, in key-scaled units (reinhard; default the image's largest)");
    render
        ->add_option("--white-balance", a.whiteBalance,
                     "none, a colour temperature (3000K), grey-world or region:x,y,w,h: adapted to D65 (Bradford)")
        ->default_str("none");
    render->add_option("--ocio-config", a.display.ocioConfig,
                       "OpenColorIO config file (default: rayrad's embedded sRGB config)");
    render->add_option("--display", a.display.display, "OCIO display (default: the config's default)");
    render->add_option(
        "--view", a.display.view,
        "OCIO view (default: the display's default; the embedded config: Standard, \"ACES 1.0 SDR-video\", Raw)");
    render
        ->add_option("--snapshots", a.snapshots,
                     "Also render K images during the solve (NAME.snap01.EXT ...), evenly spaced in log unshot energy")
        ->check(CLI::Range(0, 100));
    render->add_option("--false-colour", a.reports.falseColour,
                       "Also write the rendering's luminance in false colour (.png/.jpg; log scale, legend in cd/m²)");
    render->add_flag("--allow-black", a.allowBlack,
                     "Write the image even when every pixel is black (otherwise that is an error, exit 4)");
    addReports(render, a.reports);
}

void addSolve(CLI::App& cli, SolveArgs& a) {
    auto* solve = cli.add_subcommand("solve", "Solve the lighting and report illuminance at the sensors (no image)");
    addCommon(solve, a.common);
    solve->add_option("--sensors", a.csv, "Write the sensor table as CSV");
    solve->add_option(
        "--save", a.save,
        "Write the solution (FILE.rrs): render --solution FILE.rrs then renders any view without solving");
    addReports(solve, a.reports);
}

void addAnnual(CLI::App& cli, AnnualArgs& a) {
    auto* annual = cli.add_subcommand(
        "annual", "A year of daylight at the sensors from a weather file: daylight coefficients (one solve per sky "
                  "patch), then every hour; DA, sDA, ASE, UDI and EN 17037");
    addCommon(annual, a.common);
    annual->add_option("--weather", a.weather, "The EnergyPlus weather file (.epw): place, time zone, hourly light")
        ->required();
    annual
        ->add_option("--sky-patches", a.skyPatches,
                     "Sky patches of the coefficients: 145 (Tregenza), 577 or 2305 (Reinhart's subdivisions)")
        ->default_str("145");
    annual->add_option("--occupancy", a.occupancy, "Occupied hours on the clock, START-END in h, every day")
        ->default_str("8-18");
    annual
        ->add_option("--daylight-saving", a.daylightSaving,
                     "Summer time of the occupancy's clock: none, us (2nd Sunday of March to 1st of November) or eu "
                     "(last Sunday of March to last of October)")
        ->default_str("none");
    annual->add_option("--metrics", a.metrics, "Write each sensor's metrics as CSV");
    annual->add_option("--hourly", a.hourly,
                       "Write every hour's illuminance and direct sun at every sensor (binary float32, layout in "
                       "docs/cli.md)");
    annual->add_option("--plan", a.plan, "Write each grid's DA, ASE sun hours and UDI as false-colour plans (.png/.jpg)");
    annual->add_option("--report", a.report, "Write the study as JSON");
    annual
        ->add_option("--dimming", a.dimming,
                     "LX: daylight-linked dimming: per sensor, the share of the scene's lamps' full-output energy "
                     "needed to make up the daylight to LX in the occupied hours (ideal continuous dimming)")
        ->check(CLI::Range(1e-6, 1e6));
    annual->add_option("--hour", a.hours,
                       "MM-DDTHH: also print that hour's illuminance at the single sensors, by part (the weather "
                       "file's hour ending at HH:00 standard time), to hold against a solve of that hour's sky "
                       "(repeatable)");
    annual->add_option("--dimming-control", a.dimmingControls,
                       "GROUP=SENSOR: with --dimming, the light group dims by the daylight at that sensor (default: "
                       "the sensor it lights most; repeatable)");
    annual->add_option("--image", a.images,
                       "MM-DDTHH=FILE: render the scene's camera in that hour from the daylight coefficients, without a "
                       "solve of the hour (.exr/.png/.jpg; repeatable; daylight only, the lamps left out)");
}

void addExport(CLI::App& cli, ExportArgs& a) {
    auto* exporter = cli.add_subcommand("export",
                                        "Write the lit mesh as binary glTF (.glb) for walkthroughs: light baked into "
                                        "vertex colours, an unlit material, absolute luminance kept in _LUMINANCE");
    addCommon(exporter, a.common);
    exporter->add_option("-o,--output", a.output, "The .glb file")->required();
    exporter->add_option("--solution", a.solution, "Use a solution saved by solve --save (no solve)");
    exporter
        ->add_option(
            "--exposure", a.exposure,
            "\"auto\" (the log-average luminance of the scene camera's view, else of the solution → 0.18) or stops: "
            "2^stops per cd/m²")
        ->default_str("auto");
    exporter->add_option("--tonemap", a.tone, "Tone operator: exposure, tumblin-rushmeier, ward or reinhard")
        ->default_str("exposure");
    exporter->add_option("--white-balance", a.whiteBalance, "none, a colour temperature (3000K) or grey-world")
        ->default_str("none");
}

void addSweep(CLI::App& cli, SweepOptions& a) {
    auto* sweep = cli.add_subcommand("sweep",
                                     "Expand a grid of scene values into independent jobs (one rayrad command line "
                                     "each) for GNU parallel or a Slurm job array");
    sweep->add_option("scene", a.scene, "Scene file")->required();
    sweep
        ->add_option("--vary", a.vary,
                     "KEY=V1,V2,...: a --set key and the values it takes (repeatable; "
                     "every combination is a job)")
        ->required();
    sweep
        ->add_option("--run", a.command,
                     "The rayrad subcommand and options of every job; {job} becomes the job's number, e.g. "
                     "\"solve --sensors out/{job}.csv\"")
        ->default_str("solve");
    sweep->add_option("--jobs", a.jobsFile, "The jobs file to write (a .csv of each job's values beside it)")
        ->required();
    sweep->add_option("--rayrad", a.rayrad, "The rayrad the jobs run (default: this one's absolute path)");
}

void addInfo(CLI::App& cli, InfoArgs& a) {
    auto* info = cli.add_subcommand(
        "info", "Counts, and the stages the scene needs; for an .ies or .ldt file, its photometry and UGR table");
    addCommon(info, a.common);
    info->add_flag("--ugr-table", a.ugrTable,
                   "For an .ies or .ldt file: its UGR table (CIE 190 tabular method: rooms 2H to 12H, five "
                   "reflectance combinations, viewed crosswise and endwise)");
    info->add_option("--ugr-spacing", a.ugrSpacing,
                     "The table's luminaire spacing S / H (0.25 as most catalogues; 1 as CIE 190's standard-condition "
                     "table)")
        ->default_str("0.25")
        ->check(CLI::Range(0.05, 4.0));
    info->add_option("--ugr-csv", a.ugrCsv, "Also write the UGR table as CSV");
}

void addMerge(CLI::App& cli, MergeArgs& a) {
    auto* merge =
        cli.add_subcommand("merge", "Join the tiles of one rendering (render --tile I/N) into the whole image");
    merge
        ->add_option("-o,--output", a.outputs,
                     "Output image(s): .exr (bit-identical to rendering the whole), .png, .jpg")
        ->required()
        ->allow_extra_args(false);  // -o takes one file; the rest are tiles
    merge->add_option("tiles", a.tiles, "The tile EXR files, all N of them, in any order")->required();
}

void addCompare(CLI::App& cli, CompareOptions& a) {
    auto* compare = cli.add_subcommand("compare",
                                       "Compare an image (a rendering) against a reference (a photograph or "
                                       "another rendering) in luminance; exit 1 when a --fail-above bound is exceeded");
    compare->add_option("a", a.a, "The image under test (EXR, PNG, JPEG); calibrated onto the reference")->required();
    compare->add_option("b", a.b, "The reference image")->required();
    compare->add_option("--a-space", a.aSpace, "linear, srgb or auto (EXR linear, PNG/JPEG sRGB)")->default_str("auto");
    compare->add_option("--b-space", a.bSpace, "as --a-space, for the reference")->default_str("auto");
    compare->add_option("--align", a.alignFile,
                        "JSON file of 4 or more corresponding points [{\"a\": [x, y], \"b\": [x, y]}] (pixels from the "
                        "top-left): a is resampled onto b's grid through their homography");
    compare->add_option(
        "--regions", a.regionsFile,
        "JSON file of named regions [{\"name\", \"x\", \"y\", \"width\", \"height\"}] with their own figures");
    compare
        ->add_option(
            "--calibrate", a.calibrate,
            "none, exposure (one least-squares factor) or channels (one per channel: exposure and white balance)")
        ->default_str("exposure");
    compare->add_option("--diff-map", a.diffMap, "Write |relative luminance difference| in false colour (.png/.jpg)");
    compare->add_option("--side-by-side", a.sideBySide, "Write the calibrated image and the reference side by side");
    compare->add_option("--report", a.report, "Write the figures as JSON");
    compare->add_option("--csv", a.csv, "Write the figures as CSV, one row per region");
    compare->add_option(
        "--fail-above", a.failAbove,
        "METRIC=VALUE, repeatable: exit 1 when the whole image's figure exceeds it (mean_abs_rel_pct, "
        "median_abs_rel_pct, p95_abs_rel_pct, abs_mean_rel_pct, rms_log, ssim_loss = 1 − SSIM, mean_delta_e2000, "
        "p95_delta_e2000, mean_flip)");
}

void addGlare(CLI::App& cli, GlareArgs& a) {
    auto* glare = cli.add_subcommand(
        "glare", "Glare from a 180° fisheye rendering (EXR in cd/m²): its glare sources, UGR and DGP with its class");
    glare->add_option("image", a.image, "The fisheye image, as rayrad renders a camera with \"projection\": \"fisheye\"")
        ->required();
    glare->add_option("--threshold", a.threshold, "A glare source is brighter than this luminance, cd/m²");
    glare
        ->add_option("--threshold-factor", a.thresholdFactor,
                     "Without --threshold: a glare source is this many times brighter than the field's mean luminance")
        ->default_str("5")
        ->check(CLI::Range(1.0, 1e6));
    glare->add_option("--marked", a.marked, "Write the fisheye with the glare sources tinted and numbered (.png/.jpg)");
    glare->add_option("--report", a.report, "Write the figures and the sources as JSON");
}

/// A validation's output directory and, when `threads` is given, its worker threads per run.
void addValidationRun(CLI::App* cmd, std::string& outDir, int* threads) {
    cmd->add_option("--out", outDir, "Output directory")->default_str(outDir);
    if (threads)
        cmd->add_option("--threads", *threads, "Worker threads per run (default: all cores)")
            ->check(CLI::Range(0, kMaxThreads));
}

void addValidate(CLI::App& cli, CommandLine& args) {
    auto* validate = cli.add_subcommand("validate", "Reproduce a validation from the paper on this machine");
    validate->require_subcommand(1);

    ValidateOptions& cube = args.validateCube;
    cube.scene = bundledPath(cube.scene);
    auto* validateCube = validate->add_subcommand(
        "cube", "The empty cube: mesh sweep and cluster sweep (paper Tables 2-3), ablations, error-vs-time plots");
    validateCube->add_flag("--quick", cube.quick, "A subset at 1 200 and 4 800 triangles (about a minute)");
    validateCube->add_option("--scene", cube.scene, "The cube scene")->default_str(cube.scene);
    addValidationRun(validateCube, cube.outDir, &cube.threads);

    ValidateSphereOptions& sphere = args.validateSphere;
    sphere.sceneDir = bundledPath(sphere.sceneDir);
    auto* validateSphere = validate->add_subcommand(
        "sphere",
        "The sphere with mirrors: SPH2 and SPH4, 768 and 12 288 triangles, clusters on and off (paper Table 4)");
    validateSphere->add_flag("--quick", sphere.quick, "The 768-triangle sphere only (seconds)");
    validateSphere->add_option("--scenes", sphere.sceneDir, "Directory with sph2.json and sph4.json")
        ->default_str(sphere.sceneDir);
    addValidationRun(validateSphere, sphere.outDir, &sphere.threads);

    ValidateLuminaireOptions& luminaire = args.validateLuminaire;
    luminaire.dataDir = bundledPath(luminaire.dataDir);
    auto* validateLuminaire = validate->add_subcommand(
        "luminaire", "Every bundled photometric file: direct light from its table, a closed sphere's indirect light");
    validateLuminaire->add_option("--data", luminaire.dataDir, "Directory with .ies and .ldt files")
        ->default_str(luminaire.dataDir);
    addValidationRun(validateLuminaire, luminaire.outDir, nullptr);

    validate->add_subcommand("daylight",
                             "The sun's position, the CIE skies, the sky and the sun through openings, against references");
    validate->add_subcommand("glare",
                             "The glare formulas, CIE 190 UGR tables against CIE 190's, DIALux's and Relux's, a fisheye's "
                             "figures, UGR at an observer against the table");
}

}  // namespace

void defineCommandLine(CLI::App& cli, CommandLine& args) {
    addRender(cli, args.render);
    addSolve(cli, args.solve);
    addAnnual(cli, args.annual);
    addExport(cli, args.exporter);
    addSweep(cli, args.sweep);
    addInfo(cli, args.info);
    addMerge(cli, args.merge);
    addCompare(cli, args.compare);
    addGlare(cli, args.glare);
    addValidate(cli, args);
}

void noteChosenCommand(const CLI::App& cli, CommandLine& args) {
    using Command = CommandLine::Command;
    if (cli.got_subcommand("validate")) {
        const CLI::App* validate = cli.get_subcommand("validate");
        args.command = validate->got_subcommand("sphere")      ? Command::ValidateSphere
                       : validate->got_subcommand("luminaire") ? Command::ValidateLuminaire
                       : validate->got_subcommand("daylight")  ? Command::ValidateDaylight
                       : validate->got_subcommand("glare")     ? Command::ValidateGlare
                                                               : Command::ValidateCube;
        return;
    }
    const std::pair<const char*, Command> names[] = {
        {"render", Command::Render}, {"solve", Command::Solve}, {"export", Command::Export},  {"sweep", Command::Sweep},
        {"annual", Command::Annual},
        {"info", Command::Info},     {"merge", Command::Merge}, {"compare", Command::Compare},
        {"glare", Command::Glare}};
    for (const auto& [name, command] : names)
        if (cli.got_subcommand(name)) args.command = command;
}

const CommonArgs* CommandLine::common() const {
    switch (command) {
        case Command::Render:
            return &render.common;
        case Command::Solve:
            return &solve.common;
        case Command::Annual:
            return &annual.common;
        case Command::Export:
            return &exporter.common;
        case Command::Info:
            return &info.common;
        default:
            return nullptr;
    }
}

}  // namespace rayrad::app
