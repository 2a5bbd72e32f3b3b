#include <app/validate_sphere.h>

#include <app/validate_runs.h>
#include <core/input_error.h>
#include <core/output_file.h>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>

namespace rayrad::app {

namespace {
namespace fs = std::filesystem;
using nlohmann::json;

struct SphereRun {
    std::string scene;     ///< "sph2" or "sph4"
    int subdivisions;      ///< 12·n² triangles in the full sphere
    bool clusters;
    double paperBound;     ///< % (Table 4's largest error for the 768-triangle sphere)
};

std::string errors(const json& report, const char* key) {
    std::string out;
    for (const char* name : {"A", "B", "C"}) {
        std::string cell = "–";
        for (const auto& s : report["sensors"])
            if (s["name"] == name && s.contains("ref_total_lx")) {
                double ref = s["ref_total_lx"];
                double ind = std::string(key) == "vertex" ? s.value("indirect_vertex_lx", 0.0) : s["indirect_lx"].get<double>();
                cell = fmt::format("{:+.2f}", 100 * (s["direct_lx"].get<double>() + ind - ref) / ref);
            }
        out += (out.empty() ? "" : " / ") + cell;
    }
    return out;
}

}  // namespace

int validateSphere(const ValidateSphereOptions& o) {
    const std::string csvPath = prepareResults(o.outDir);
    std::error_code ec;
    std::vector<SphereRun> runs;
    for (int n : {8, 32})
        for (bool clusters : {true, false})
            for (const char* scene : {"sph2", "sph4"})
                if (!(o.quick && n > 8)) runs.push_back({scene, n, clusters, std::string(scene) == "sph2" ? 2.3 : 6.5});
    fmt::print("rayrad validate sphere{}: {} runs, results in {}\n", o.quick ? " --quick" : "", runs.size(), o.outDir);
    std::string table =
        "| scene | sphere triangles | patches | clusters | gathered total err A / B / C % | vertex total err A / B / C % "
        "| solve s | total s | paper (768) within % |\n|---|---|---|---|---|---|---|---|---|\n";
    std::string csv = "scene,sphere_triangles,patches,clusters,solve_s,total_s";
    for (const char* p : {"A", "B", "C"}) csv += fmt::format(",{0}_direct_lx,{0}_indirect_lx,{0}_ref_total_lx", p);
    csv += "\n";
    for (size_t i = 0; i < runs.size(); ++i) {
        const SphereRun& r = runs[i];
        std::string scene = (fs::path(o.sceneDir) / (r.scene + ".json")).string();
        if (!fs::is_regular_file(scene, ec)) throw InputError(placeMessage(scene, "", "no such file"));
        std::string base = (fs::path(o.outDir) / fmt::format("{}_{}_{}", r.scene, 12 * r.subdivisions * r.subdivisions,
                                                               r.clusters ? "clusters" : "none")).string();
        std::vector<std::string> args = {selfExe(), "solve", scene, "-q", "--report", base + ".json",
                                         "--set", fmt::format("objects.0.subdivisions={}", r.subdivisions),
                                         "--set", fmt::format("clusters.enabled={}", r.clusters)};
        if (o.threads > 0) args.insert(args.end(), {"--threads", std::to_string(o.threads)});
        fmt::print("[{}/{}] {} {} triangles, clusters {} ... ", i + 1, runs.size(), r.scene,
                   12 * r.subdivisions * r.subdivisions, r.clusters ? "on" : "off");
        std::fflush(stdout);
        if (int rc = runChild(args, base + ".log"); rc != 0) {
            fmt::print("FAILED (exit {}, see {}.log)\n", rc, base);
            return 1;
        }
        std::ifstream in(base + ".json");
        json report = json::parse(in);
        double solve = report["solve"]["seconds"], total = report["total_seconds"];
        fmt::print("{:.2f} s solve, {:.2f} s in all\n", solve, total);
        table += fmt::format("| {} | {} | {} | {} | {} | {} | {:.2f} | {:.2f} | {} |\n", r.scene == "sph2" ? "SPH2" : "SPH4",
                             12 * r.subdivisions * r.subdivisions, report["patches"].get<size_t>(),
                             r.clusters ? "on" : "off", errors(report, "gather"), errors(report, "vertex"), solve, total,
                             r.paperBound);
        csv += fmt::format("{},{},{},{},{:.4f},{:.4f}", r.scene, 12 * r.subdivisions * r.subdivisions,
                           report["patches"].get<size_t>(), r.clusters ? 1 : 0, solve, total);
        for (const char* p : {"A", "B", "C"}) {
            std::string cells = ",,,";
            for (const auto& s : report["sensors"])
                if (s["name"] == p && s.contains("ref_total_lx"))
                    cells = fmt::format(",{:.4f},{:.4f},{:.4f}", s["direct_lx"].get<double>(),
                                        s["indirect_lx"].get<double>(), s["ref_total_lx"].get<double>());
            csv += cells;
        }
        csv += "\n";
    }
    fmt::print("\n### Sphere with mirrors (paper Table 4)\n\n{}", table);
    writeFileAtomically(csvPath, csv);
    fmt::print("\nwrote {} and one report and log per run\n", csvPath);
    return 0;
}

}  // namespace rayrad::app
