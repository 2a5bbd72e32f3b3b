// The command line: every subcommand's arguments and options, as `rayrad --help` lists them.
#pragma once

#include <app/compare.h>
#include <app/glare/glare_command.h>
#include <app/run_outputs.h>
#include <app/sweep.h>
#include <app/validate_cube.h>
#include <app/validate_luminaire.h>
#include <app/validate_sphere.h>
#include <tonemap/display_transform.h>

#include <optional>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace rayrad::app {

constexpr int kMaxThreads = 4096;

/// What render, solve, export and info share.
struct CommonArgs {
    std::string scene;              ///< the scene file; "-" reads standard input
    std::vector<std::string> sets;  ///< --set KEY=VALUE
    int threads = 0;                ///< 0: all cores
    bool quiet = false;
};

struct RenderArgs {
    CommonArgs common;
    std::vector<std::string> outputs;
    std::string csv;
    std::optional<int> spp, seed;
    std::string exposure = "auto", tone = "exposure", whiteBalance = "none";
    tonemap::DisplayOptions display;  ///< the tone operator's parameters and the OCIO display
    int snapshots = 0;
    bool allowBlack = false;
    ReportArgs reports;
    std::vector<std::string> cameras;
    std::string solution, tile, frames;
};

/// rayrad info: the scene (or photometric file), and for a photometric file its UGR table.
struct InfoArgs {
    CommonArgs common;
    bool ugrTable = false;     ///< --ugr-table
    double ugrSpacing = 0.25;  ///< --ugr-spacing, S / H
    std::string ugrCsv;        ///< --ugr-csv FILE
};

struct SolveArgs {
    CommonArgs common;
    std::string csv, save;
    ReportArgs reports;
};

/// rayrad annual: a year of daylight from a weather file.
struct AnnualArgs {
    CommonArgs common;
    std::string weather;          ///< the EPW file
    int skyPatches = 145;         ///< 145, 577 or 2305
    std::string occupancy = "8-18";
    std::string daylightSaving = "none";
    std::string metrics, hourly, plan, report;  ///< outputs
    std::vector<std::string> hours;  ///< "MM-DDTHH": print those hours' illuminance at the sensors, by part
    double dimming = 0;              ///< lx: daylight-linked dimming of the lamps to this target (0: none)
    std::vector<std::string> dimmingControls;  ///< "GROUP=SENSOR": the point a light group dims by
    std::vector<std::string> images;  ///< "MM-DDTHH=FILE": render the camera in that hour from the coefficients
};

struct ExportArgs {
    CommonArgs common;
    std::string output, solution, exposure = "auto", tone = "exposure", whiteBalance = "none";
};

struct MergeArgs {
    std::vector<std::string> outputs, tiles;
};

/// Every subcommand's arguments; `command` says which one the command line chose.
struct CommandLine {
    enum class Command {
        Render,
        Solve,
        Export,
        Sweep,
        Info,
        Merge,
        Compare,
        ValidateCube,
        ValidateSphere,
        ValidateLuminaire,
        ValidateDaylight,
        ValidateGlare,
        Annual,
        Glare
    };
    Command command = Command::Info;
    RenderArgs render;
    SolveArgs solve;
    AnnualArgs annual;
    ExportArgs exporter;
    InfoArgs info;
    SweepOptions sweep;
    MergeArgs merge;
    CompareOptions compare;
    GlareArgs glare;
    ValidateOptions validateCube;
    ValidateSphereOptions validateSphere;
    ValidateLuminaireOptions validateLuminaire;
    /// The chosen command's common arguments (render, solve, export, info), or null.
    const CommonArgs* common() const;
};

/// Declares every subcommand and option on `cli`; parsing fills `args`.
void defineCommandLine(CLI::App& cli, CommandLine& args);

/// After cli.parse(): which subcommand it was (stored in args.command).
void noteChosenCommand(const CLI::App& cli, CommandLine& args);

}  // namespace rayrad::app
