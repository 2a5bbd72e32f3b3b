#include <app/validate_glare.h>

#include <app/glare/fisheye_glare.h>
#include <app/glare/glare_formulas.h>
#include <app/pipeline.h>
#include <app/validate_runs.h>
#include <app/validation_checks.h>
#include <core/input_error.h>
#include <core/input_file.h>
#include <scene/photometry.h>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <optional>
#include <fstream>
#include <sstream>

#include <unistd.h>

namespace rayrad::app {

UgrReference readUgrReference(const std::string& path) {
    std::istringstream in(readInputFile(path, "UGR reference table", size_t(1) << 20));
    UgrReference rows;
    std::string line;
    int number = 0;
    while (std::getline(in, line)) {
        ++number;
        if (line.find_first_not_of(" \r") == std::string::npos) continue;
        std::vector<std::optional<double>> row;
        std::stringstream fields(line);
        std::string f;
        while (std::getline(fields, f, ',')) {
            if (f.find('<') != std::string::npos) {
                row.emplace_back();
                continue;
            }
            char* end = nullptr;
            const double v = std::strtod(f.c_str(), &end);
            if (end == f.c_str() || !std::isfinite(v))
                throw InputError(placeMessage(path, fmt::format("line {}", number), "expected a UGR, got \"" + f + "\""));
            row.push_back(v);
        }
        if (row.size() != 10)
            throw InputError(placeMessage(path, fmt::format("line {}", number),
                                          fmt::format("expected 10 values, got {}", row.size())));
        rows.push_back(std::move(row));
    }
    if (rows.size() != kUgrTableRooms.size())
        throw InputError(placeMessage(path, "", fmt::format("expected {} rows, got {}", kUgrTableRooms.size(), rows.size())));
    return rows;
}

double largestUgrDifference(const UgrTable& ours, const UgrReference& reference, int* compared) {
    double worst = 0;
    int n = 0;
    for (size_t i = 0; i < reference.size() && i < ours.values.size(); ++i)
        for (size_t k = 0; k < 10; ++k) {
            if (!reference[i][k] || !ours.values[i][k]) continue;
            worst = std::max(worst, std::abs(*ours.values[i][k] - *reference[i][k]));
            ++n;
        }
    if (compared) *compared = n;
    return worst;
}

std::string ugrStandardRoomJson(const std::string& ldtFile, bool partition) {
    using nlohmann::json;
    json j;
    j["materials"] = {{"floor", {{"reflectance", 0.2}}},
                      {"walls", {{"reflectance", 0.5}}},
                      {"ceiling", {{"reflectance", 0.7}}}};
    auto quad = [](const char* m, json v) { return json{{"type", "quad"}, {"material", m}, {"vertices", v}}; };
    j["objects"] = {
        quad("floor", {{-4, 0, 0}, {-4, 0, 8}, {4, 0, 8}, {4, 0, 0}}),
        quad("ceiling", {{-4, 3.2, 0}, {4, 3.2, 0}, {4, 3.2, 8}, {-4, 3.2, 8}}),
        quad("walls", {{-4, 0, 0}, {4, 0, 0}, {4, 3.2, 0}, {-4, 3.2, 0}}),
        quad("walls", {{4, 0, 8}, {-4, 0, 8}, {-4, 3.2, 8}, {4, 3.2, 8}}),
        quad("walls", {{-4, 0, 8}, {-4, 0, 0}, {-4, 3.2, 0}, {-4, 3.2, 8}}),
        quad("walls", {{4, 0, 0}, {4, 0, 8}, {4, 3.2, 8}, {4, 3.2, 0}}),
    };
    if (partition)
        j["objects"].push_back(
            {{"type", "box"}, {"material", "walls"}, {"min", {0, 0, 0.4}}, {"max", {4, 3.2, 0.5}}, {"facing", "outward"}});
    j["lights"] = json::array();
    for (double z : {1.0, 3.0, 5.0, 7.0})
        for (double x : {-3.0, -1.0, 1.0, 3.0})
            j["lights"].push_back({{"type", "luminaire"},
                                   {"file", ldtFile},
                                   {"position", {x, 3.19, z}},
                                   {"aim", {x, 0, z}},
                                   {"c0_toward", {0, 0, -1}}});
    j["observers"] = {{{"name", "eye"}, {"position", {0, 1.2, 0.02}}, {"direction", {0, 0, 1}}, {"task", "office"}}};
    return j.dump();
}

SyntheticFisheye::SyntheticFisheye() {
    constexpr int n = 601;
    constexpr double background = 100, alpha = 5 * kPi / 180;
    centre = glm::normalize(Vec3(std::tan(10 * kPi / 180), std::tan(20 * kPi / 180), 1));
    HdrImage image(n, n);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x)
            if (auto p = fisheyePixel(n, n, x, y))
                image.at(x, y) = Rgb(glm::dot(p->direction, centre) > std::cos(alpha) ? luminance : background);
    found = analyseFisheye(image, {}, "synthetic fisheye");
    // ∫ cos θ dω over a cone about an axis at θ_c: cos θ_c π sin² α.
    omega = 2 * kPi * (1 - std::cos(alpha));
    const double sourcePart = centre.z * kPi * std::sin(alpha) * std::sin(alpha);
    ev = kPi * background + (luminance - background) * sourcePart;
    GlareSource exact;
    exact.luminance = luminance;
    exact.solidAngle = omega;
    exact.positionIndex = positionIndex(centre);
    dgp = daylightGlareProbability(ev, {exact});
    ugr = unifiedGlareRating((ev - luminance * sourcePart) / kPi, {exact}).value_or(0.0);
}

int validateGlare() {
    std::vector<Check> checks;
    const double s = std::sqrt(0.5);
    checks.push_back(timed("Guth's position index 45° straight above: CIE 117's table, 7.00", 2, "%", [&] {
        return 100 * (positionIndex(Vec3(0, s, s)) / 7.00 - 1);
    }));
    checks.push_back(timed("Guth's position index 45° level to the side: CIE 117's table, 2.11", 5, "%", [&] {
        return 100 * (positionIndex(Vec3(s, 0, s)) / 2.11 - 1);
    }));
    checks.push_back(timed("UGR of one source (L 10 000, ω 0.01, P 2, L_b 20): by hand 27.9588", 1e-3, "UGR", [&] {
        GlareSource src;
        src.luminance = 10000, src.solidAngle = 0.01, src.positionIndex = 2;
        return *unifiedGlareRating(20, {src}) - 27.9588;
    }));
    checks.push_back(timed("DGP of one source (L 5 000, ω 0.005, P 1.5) at 2 000 lx: by hand 0.278860", 1e-5, "", [&] {
        GlareSource src;
        src.luminance = 5000, src.solidAngle = 0.005, src.positionIndex = 1.5;
        return daylightGlareProbability(2000, {src}) - 0.278860;
    }));
    checks.push_back(timed("the walls' transfer factors, rooms 4H × 4H and 12H × 8H: CIE 190 Table 5", 6e-4, "", [&] {
        const auto a = wallTransferFactors(4, 4, 1, {0.7, 0.5, 0.2}), b = wallTransferFactors(12, 8, 1, {0.7, 0.5, 0.2});
        return std::max({std::abs(a.fromFloor - 0.142), std::abs(a.fromWalls - 0.265), std::abs(a.fromCeiling - 0.389),
                         std::abs(b.fromFloor - 0.071), std::abs(b.fromWalls - 0.133), std::abs(b.fromCeiling - 0.183)});
    }));
    const std::string ldt = std::filesystem::absolute(bundledPath("tests/data/luminaires/eulumdatugr_sample_11.ldt")).string();
    const scene::Photometry example = scene::readPhotometry(ldt);
    checks.push_back(timed("UGR table of CIE 190's example luminaire, spacing 1 H: CIE 190's, largest difference", 0.3,
                           "UGR", [&] {
                               return largestUgrDifference(ugrTable(example, 1.0),
                                                           readUgrReference(bundledPath("tests/data/ugr/sample_11_cie190.csv")));
                           }));
    std::optional<UgrTable> catalogue;  // made in the first check that needs it, and timed there
    for (const char* program : {"Relux", "DIALux"})
        checks.push_back(timed(fmt::format("the same at 0.25 H: {}'s table, largest difference", program),
                               program[0] == 'R' ? 0.5 : 1.0, "UGR", [&] {
                                   if (!catalogue) catalogue = ugrTable(example, 0.25);
                                   return largestUgrDifference(
                                       *catalogue, readUgrReference(bundledPath(fmt::format(
                                                       "tests/data/ugr/sample_11_{}.csv", program[0] == 'R' ? "Relux" : "Dialux"))));
                               }));
    std::optional<SyntheticFisheye> made;
    const SyntheticFisheye* fisheyePtr = nullptr;
    checks.push_back(timed("a fisheye's 5° source: its solid angle against 2π(1 − cos α)", 1, "%", [&] {
        fisheyePtr = &made.emplace();
        return 100 * (fisheyePtr->found.sources.at(0).solidAngle / fisheyePtr->omega - 1);
    }));
    const SyntheticFisheye& fisheye = *fisheyePtr;
    checks.push_back(timed("the same fisheye's E_v against π L_bg + ΔL cos θ_c π sin² α", 0.5, "%", [&] {
        return 100 * (fisheye.found.verticalIlluminance / fisheye.ev - 1);
    }));
    checks.push_back(timed("the same fisheye's DGP against the formula on the exact source", 0.002, "", [&] {
        return fisheye.found.dgp - fisheye.dgp;
    }));
    checks.push_back(timed("UGR at an observer in CIE 190's standard room 4H × 4H (a solve) against the table", 1, "UGR",
                           [&] {
                               const std::filesystem::path dir = std::filesystem::temp_directory_path();
                               const std::string file = (dir / fmt::format("rayrad-validate-glare-{}.json", ::getpid())).string();
                               std::ofstream(file) << ugrStandardRoomJson(ldt, false);
                               PipelineOptions quiet;
                               quiet.quiet = true;
                               const PipelineRun run = runPipeline(file, quiet);
                               std::filesystem::remove(file);
                               const auto table = ugrTableEntry(example, {4, 4}, {0.7, 0.5, 0.2}, false, 1.0);
                               return run.glare.at(0).ugr.value() - table.ugr.value();
                           }));
    return printChecks(checks);
}

}  // namespace rayrad::app
