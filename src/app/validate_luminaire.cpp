#include <app/validate_luminaire.h>

#include <app/pipeline.h>
#include <app/validate_runs.h>
#include <core/input_error.h>
#include <core/output_file.h>
#include <radiosity/radiosity.h>
#include <scene/photometry.h>
#include <scene/scene.h>

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>

namespace rayrad::app {

namespace {
namespace fs = std::filesystem;

constexpr double kHeight = 3.0;           ///< m, luminaire above the floor (more for a large opening)
constexpr double kMaxGammaDeg = 80.0;     ///< farther out the floor points are too far away
constexpr double kRho = 0.5;              ///< the closed sphere's reflectance
constexpr double kDirectBound = 1e-6;     ///< relative: exact at the table's nodes
constexpr double kIndirectBound = 0.015;  ///< relative: the tessellated sphere (as for a point light)
constexpr double kEnergyBound = 1e-3;     ///< relative

/// The index of the stored plane nearest `c` degrees.
size_t planeNear(const scene::Photometry& p, double c) {
    size_t best = 0;
    for (size_t h = 1; h < p.horizontal.size(); ++h)
        if (std::abs(p.horizontal[h] - c) < std::abs(p.horizontal[best] - c)) best = h;
    return best;
}

std::string writeScene(const std::string& dir, const std::string& name, const std::string& json) {
    const std::string path = (fs::path(dir) / (name + ".json")).string();
    writeFileAtomically(path, json);
    return path;
}

struct Result {
    std::string file;
    size_t points = 0, sphereSensors = 0;
    double directError = 0, indirectError = 0, energyError = 0, flux = 0, seconds = 0;
};

Result validateFile(const std::string& file, const std::string& outDir) {
    Result r;
    r.file = fs::path(file).filename().string();
    const scene::Photometry p = scene::readPhotometry(file);
    r.flux = p.integratedFlux();
    const auto start = std::chrono::steady_clock::now();
    const std::string absolute = fs::absolute(file).string();
    // (1) Direct light on a black floor at the table's nodes in the C0 and C90 planes,
    // beyond the near field (kNearFieldSizes opening sizes), where the luminaire is a point.
    const double height = std::max(
        kHeight, 1.01 * scene::kNearFieldSizes * std::max(p.width, p.length) / std::cos(kMaxGammaDeg * kPi / 180));
    // C0 along +x; C90 = (−nadir) × c0 = +y × +x = −z.
    std::string sensors;
    struct Expected {
        double lux;
    };
    std::vector<Expected> expected;
    for (double c : {0.0, 90.0}) {
        const size_t h = p.horizontal.size() == 1 ? 0 : planeNear(p, c);
        if (p.horizontal.size() > 1 && std::abs(p.horizontal[h] - c) > 1e-9) continue;  // no such plane stored
        for (size_t v = 0; v < p.vertical.size(); ++v) {
            const double gamma = p.vertical[v];
            if (gamma >= kMaxGammaDeg) break;
            const double g = gamma * kPi / 180, rho = height * std::tan(g), cr = c * kPi / 180;
            const double x = rho * std::cos(cr), z = -rho * std::sin(cr);
            sensors +=
                fmt::format("{}{{\"name\": \"p{}\", \"position\": [{:.17g}, 0, {:.17g}], \"normal\": [0, 1, 0]}}",
                            sensors.empty() ? "" : ", ", expected.size(), x, z);
            expected.push_back({p.candela[h][v] * std::pow(std::cos(g), 3) / (height * height)});  // E = I cos³γ / h²
        }
    }
    const std::string floor = fmt::format(
        R"({{"materials": {{"black": {{"reflectance": 0}}}},
            "objects": [{{"type": "quad", "material": "black", "vertices": [[-40, 0, -40], [-40, 0, 40], [40, 0, 40], [40, 0, -40]]}}],
            "lights": [{{"type": "luminaire", "file": "{}", "position": [0, {}, 0], "aim": [0, 0, 0], "c0_toward": [1, 0, 0]}}],
            "sensors": [{}], "radiosity": {{"max_edge": 10}}}})",
        absolute, height, sensors);
    PipelineOptions quiet;
    quiet.quiet = true;
    const auto direct = runPipeline(writeScene(outDir, r.file + ".floor", floor), quiet);
    const double peak =
        std::max_element(expected.begin(), expected.end(), [](auto& a, auto& b) { return a.lux < b.lux; })->lux;
    for (size_t i = 0; i < expected.size(); ++i) {
        if (expected[i].lux < 1e-6 * peak) continue;
        ++r.points;
        const double got = luminance(direct.sensors[i].value.direct);
        r.directError = std::max(r.directError, std::abs(got / expected[i].lux - 1));
    }
    // (2) The closed sphere: uniform indirect ρ/(1−ρ) Φ/A, and the energy account. On the
    // tessellated sphere a point does not receive the light reflected by the facets in its
    // own plane, which matters where the direct light is concentrated (a narrow beam's
    // spot): the indirect is compared at the sensors (of 14, along the axes and the
    // diagonals) that get less than a fifth of the largest direct illuminance.
    std::string sphereSensors;
    std::vector<Vec3> directions;
    for (int a = 0; a < 3; ++a)
        for (double sign : {1.0, -1.0}) {
            Vec3 d(0.0);
            d[a] = sign;
            directions.push_back(d);
        }
    for (double x : {-1.0, 1.0})
        for (double y : {-1.0, 1.0})
            for (double z : {-1.0, 1.0}) directions.push_back(glm::normalize(Vec3(x, y, z)));
    for (size_t i = 0; i < directions.size(); ++i)
        sphereSensors += fmt::format(
            "{}{{\"name\": \"s{}\", \"position\": [{:.17g}, {:.17g}, {:.17g}], \"normal\": [{:.17g}, {:.17g}, "
            "{:.17g}]}}",
            i ? ", " : "", i, directions[i].x, directions[i].y, directions[i].z, -directions[i].x, -directions[i].y,
            -directions[i].z);
    const std::string sphere = fmt::format(
        R"({{"materials": {{"m": {{"reflectance": {}}}}},
            "objects": [{{"type": "sphere", "material": "m", "radius": 1, "subdivisions": 16, "facing": "inward"}}],
            "lights": [{{"type": "luminaire", "file": "{}", "position": [0, 0, 0], "aim": [0, -1, 0], "c0_toward": [1, 0, 0]}}],
            "sensors": [{}],
            "radiosity": {{"max_edge": 10, "stop_unshot": 1e-5}}}})",
        kRho, absolute, sphereSensors);
    const auto closed = runPipeline(writeScene(outDir, r.file + ".sphere", sphere), quiet);
    const double uniform = kRho / (1 - kRho) * r.flux / closed.mesh.totalArea();
    double brightest = 0;
    for (const auto& s : closed.sensors) brightest = std::max(brightest, luminance(s.value.direct));
    for (const auto& s : closed.sensors) {
        if (luminance(s.value.direct) > 0.2 * brightest) continue;
        ++r.sphereSensors;
        r.indirectError = std::max(r.indirectError, std::abs(luminance(s.value.indirect) / uniform - 1));
    }
    const auto balance = energyBalanceOf(closed);
    r.energyError = std::abs(balance.relativeError());
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return r;
}

}  // namespace

int validateLuminaire(const ValidateLuminaireOptions& o) {
    const std::string csvPath = prepareResults(o.outDir);
    std::vector<std::string> files;
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(o.dataDir, ec)) {
        if (scene::isPhotometricFile(e.path().string())) files.push_back(e.path().string());
    }
    if (ec || files.empty()) throw InputError(placeMessage(o.dataDir, "", "no .ies or .ldt files here"));
    std::sort(files.begin(), files.end());
    fmt::print("rayrad validate luminaire: {} files from {}, results in {}\n\n", files.size(), o.dataDir, o.outDir);
    std::string table =
        "| file | flux lm | direct: points, largest error | closed sphere: sensors, indirect error | energy not "
        "accounted | s |\n"
        "|---|---|---|---|---|---|\n";
    std::string csv = "file,flux_lm,direct_points,direct_max_err,sphere_sensors,indirect_max_err,energy_err,seconds\n";
    bool ok = true;
    for (const auto& f : files) {
        const Result r = validateFile(f, o.outDir);
        ok &= r.sphereSensors >= 3 && r.directError <= kDirectBound && r.indirectError <= kIndirectBound &&
              r.energyError <= kEnergyBound;
        table +=
            fmt::format("| {} | {:.2f} | {}, {:.1e} | {}, {:.2f} % | {:.4f} % | {:.1f} |\n", r.file, r.flux, r.points,
                        r.directError, r.sphereSensors, 100 * r.indirectError, 100 * r.energyError, r.seconds);
        csv += fmt::format("{},{:.6f},{},{:.3e},{},{:.6e},{:.6e},{:.3f}\n", r.file, r.flux, r.points, r.directError,
                           r.sphereSensors, r.indirectError, r.energyError, r.seconds);
    }
    fmt::print(
        "{}\nbounds: direct {:.0e} (exact at the table's nodes), indirect {:.1f} % (the tessellated sphere), "
        "energy {:.1f} %: {}\n",
        table, kDirectBound, 100 * kIndirectBound, 100 * kEnergyBound, ok ? "all within" : "SOME BEYOND");
    writeFileAtomically(csvPath, csv);
    fmt::print("wrote {}\n", csvPath);
    return ok ? 0 : 1;
}

}  // namespace rayrad::app
