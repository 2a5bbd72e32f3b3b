// Benchmark: does the indirect light an image shows agree with a final gather, anywhere
// on a scene's surfaces? One solve of SCENE; then random points, spread over the lit
// reflecting surfaces in proportion to their area (or, with --view, the surfaces the
// scene's camera sees first through random pixels: the image's own pixels, weighted as
// the image weights them), each evaluated as a sensor: the
// indirect light interpolated from the mesh's vertex values (what the ray tracer shows)
// against the final gather there. Prints, over the points whose indirect light is at
// least 10 % of their total (where an image error in the indirect light shows) and whose
// total is at least 1 % of the bright points' (the 90th percentile; darker is black in
// any exposure that shows the scene: the outside of a box, a gap behind a wall):
//   - |mesh − gather| / total: median, 95th percentile, max (the image's relative error:
//     a pixel is ρ (direct + indirect) / π, so the indirect light's difference over the
//     total is the pixel's);
//   - |mesh − gather| / gather: the share of points beyond 5 %;
// the worst points with their place, and the gather's CPU time a point (median, 90th
// percentile, max: what a sensor costs there), beside the solve's.
// Usage: build/bench/surface_agreement SCENE [points (400)] [key=value ...] [--view | --both] [--solution=FILE.rrs]
//        [--csv=FILE]
//        (key=value: scene settings, as with --set, which may precede each; --view: points
//        seen by the camera instead of spread over the surfaces, --both: both sets, from
//        one solve; --solution:
//        a solution saved by rayrad solve --save for the same scene and settings; --csv:
//        every point's place, direct light, mesh and gathered indirect light, CPU and
//        gathers, its patch and the patch's own solved indirect light, its material and
//        whether the patch is covered; with --both, the view's points)
#include "bench_main.h"

#include <app/pipeline.h>
#include <core/random.h>
#include <core/stage_report.h>
#include <raytrace/view_samples.h>

#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <string>
#include <vector>

using namespace rayrad;

namespace {

double threadCpuSeconds() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

struct Point {
    size_t patch = 0;
    scene::Sensor sensor;
    radiosity::SensorValue value;
    double cpu = 0;      ///< s, this point's gather
    size_t gathers = 0;  ///< point gathers it took: its own and the corner and midpoint re-gathers
};

double quantile(std::vector<double> v, double q) {
    if (v.empty()) return 0;
    std::sort(v.begin(), v.end());
    return v[std::min(v.size() - 1, static_cast<size_t>(q * static_cast<double>(v.size())))];
}

/// `count` points, area-weighted over the patches that reflect and do not emit.
std::vector<Point> samplePoints(const scene::Scene& scene, const radiosity::PatchMesh& mesh, int count) {
    std::vector<double> cumulative;
    std::vector<size_t> patches;
    double total = 0;
    for (size_t i = 0; i < mesh.patches.size(); ++i) {
        const scene::Material& m = scene.materials[mesh.patches[i].material];
        if (luminance(m.reflectance) <= 0 || luminance(m.emission) > 0 || m.kind != scene::SurfaceKind::Diffuse)
            continue;
        total += mesh.patches[i].area;
        cumulative.push_back(total);
        patches.push_back(i);
    }
    std::vector<Point> points;
    Random rng(12345);
    for (int k = 0; k < count && total > 0; ++k) {
        const double a = rng.nextDouble() * total;
        const size_t j = std::upper_bound(cumulative.begin(), cumulative.end(), a) - cumulative.begin();
        const radiosity::Patch& p = mesh.patches[patches[std::min(j, patches.size() - 1)]];
        double u = rng.nextDouble(), v = rng.nextDouble();
        if (u + v > 1) u = 1 - u, v = 1 - v;
        Point pt;
        pt.patch = patches[std::min(j, patches.size() - 1)];
        pt.sensor.name = fmt::format("p{}", k);
        pt.sensor.position =
            mesh.vertices[p.v[0]] * (1 - u - v) + mesh.vertices[p.v[1]] * u + mesh.vertices[p.v[2]] * v;
        pt.sensor.normal = p.normal;
        points.push_back(pt);
    }
    return points;
}

/// What the scene's camera sees first through `count` random pixels (raytrace/view_samples.h),
/// as points to evaluate.
std::vector<Point> viewPoints(const scene::Scene& scene, const radiosity::PatchMesh& mesh,
                              const raytrace::EmbreeScene& embree, int count, int& missed) {
    std::vector<Point> points;
    for (const raytrace::ViewSample& v :
         raytrace::viewSamples(scene, *scene.camera, mesh, embree, count, 12345, missed)) {
        Point pt;
        pt.patch = v.patch;
        pt.sensor.name = fmt::format("p{}", points.size());
        pt.sensor.position = v.position;
        pt.sensor.normal = v.normal;
        points.push_back(pt);
    }
    return points;
}

/// A point no camera can see: every probe a quarter of the patch size out (along the
/// normal and tilted 60° four ways) is blocked — a gap under a plate lying on the surface.
bool covered(const radiosity::PatchMesh& mesh, const Visibility& vis, const Vec3& x, const Vec3& n) {
    const auto [t1, t2] = tangentFrame(n);
    const double d = 0.25 * mesh.edgeLength, c = 0.5, s = std::sqrt(0.75);
    for (const Vec3& dir : {n, c * n + s * t1, c * n - s * t1, c * n + s * t2, c * n - s * t2})
        if (vis.visibleFromSurface(x, n, x + d * dir)) return false;
    return true;
}

/// A set of points evaluated: where they came from, and what was left out before.
struct PointSet {
    std::string what;  ///< the first line's account of the points
    std::vector<Point> points;
};

/// Each point as a sensor, alone (its own memo: what one sensor costs).
void evaluate(const app::PipelineRun& run, const radiosity::Gatherer& gatherer, std::vector<Point>& points) {
    tbb::parallel_for(size_t(0), points.size(), [&](size_t i) {
        radiosity::GatherMemo memo;
        const double t = threadCpuSeconds();
        points[i].value = radiosity::evaluateSensor(run.scene, run.mesh, run.lighting.solution, *run.lighting.lights,
                                                    *run.embree, gatherer, memo, points[i].sensor);
        points[i].cpu = threadCpuSeconds() - t;
        points[i].gathers = memo.gathers();
    });
}

void writeCsv(std::FILE* f, const app::PipelineRun& run, const std::vector<Point>& points) {
    std::fprintf(f, "x,y,z,nx,ny,nz,direct_lx,mesh_indirect_lx,gather_indirect_lx,cpu_s,gathers,patch,patch_indirect_lx,"
                    "material,covered\n");
    for (const Point& p : points) {
        // The material's name quoted as CSV quotes it (a name may hold commas).
        std::string material = run.scene.materials[run.mesh.patches[p.patch].material].name;
        for (size_t at = 0; (at = material.find('"', at)) != std::string::npos; at += 2) material.insert(at, 1, '"');
        std::fprintf(f, "%.6f,%.6f,%.6f,%.4f,%.4f,%.4f,%.6g,%.6g,%.6g,%.6g,%zu,%zu,%.6g,\"%s\",%d\n", p.sensor.position.x,
                     p.sensor.position.y, p.sensor.position.z, p.sensor.normal.x, p.sensor.normal.y, p.sensor.normal.z,
                     luminance(p.value.direct), p.value.indirectVertex ? luminance(*p.value.indirectVertex) : -1.0,
                     luminance(p.value.indirect), p.cpu, p.gathers, p.patch,
                     luminance(run.lighting.solution.indirect[p.patch]), material.c_str(),
                     run.mesh.isCovered(p.patch) ? 1 : 0);
    }
}

/// The agreement over one set's points, printed.
void summarize(const std::string& sceneFile, const app::PipelineRun& run, double solveCpu, const PointSet& set) {
    const std::vector<Point>& points = set.points;
    // A point lit at under 1 % of the bright points (the 90th percentile of the totals) is
    // black in any exposure that shows the scene: the outside of a box, a gap behind a wall.
    std::vector<double> totals;
    for (const Point& p : points)
        if (p.value.indirectVertex) totals.push_back(luminance(p.value.direct) + luminance(p.value.indirect));
    const double darkBelow = 0.01 * quantile(totals, 0.9);
    std::vector<double> ofTotal, cpu, gathers;
    int judged = 0, beyond5 = 0, dark = 0;
    std::vector<std::pair<double, const Point*>> worst;
    for (const Point& p : points) {
        cpu.push_back(p.cpu);
        gathers.push_back(static_cast<double>(p.gathers));
        if (!p.value.indirectVertex) continue;
        const double gather = luminance(p.value.indirect), mesh = luminance(*p.value.indirectVertex);
        const double total = luminance(p.value.direct) + gather;
        if (total < darkBelow) {
            ++dark;
            continue;
        }
        if (!(total > 0) || gather < 0.1 * total) continue;
        ++judged;
        const double e = std::abs(mesh - gather) / total;
        ofTotal.push_back(e);
        if (std::abs(mesh - gather) > 0.05 * gather) ++beyond5;
        worst.push_back({e, &p});
    }
    std::sort(worst.begin(), worst.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
    fmt::print(
        "{}: {} patches, solve {:.2f} CPU-s; {}, {} dark (below {:.3g} lx) left out; {} with indirect >= 10 % "
        "of total\n",
        sceneFile, run.mesh.patches.size(), solveCpu, set.what, dark, darkBelow, judged);
    fmt::print("|mesh - gather| / total: median {:.2f} %, 95th percentile {:.2f} %, max {:.1f} %\n",
               100 * quantile(ofTotal, 0.5), 100 * quantile(ofTotal, 0.95), 100 * quantile(ofTotal, 1.0));
    fmt::print("points whose mesh value is more than 5 % from its gather: {} of {} ({:.1f} %)\n", beyond5, judged,
               judged ? 100.0 * beyond5 / judged : 0.0);
    fmt::print("gather CPU a point: median {:.1f} ms, 90th percentile {:.1f} ms, max {:.1f} ms\n",
               1e3 * quantile(cpu, 0.5), 1e3 * quantile(cpu, 0.9), 1e3 * quantile(cpu, 1.0));
    fmt::print(
        "point gathers a point (its own and its re-gathers): median {:.0f}, 90th percentile {:.0f}, "
        "max {:.0f}\n",
        quantile(gathers, 0.5), quantile(gathers, 0.9), quantile(gathers, 1.0));
    fmt::print(
        "worst points (position, normal, patch area m², longest edge m: mesh lx, gather lx, direct lx; "
        "the patch's own indirect lx from the solve; material, and whether the patch is covered)\n");
    for (size_t k = 0; k < std::min<size_t>(12, worst.size()); ++k) {
        const Point& p = *worst[k].second;
        const radiosity::Patch& patch = run.mesh.patches[p.patch];
        fmt::print(
            "  {:6.2f} %  ({:.3f}, {:.3f}, {:.3f}) n ({:.2f}, {:.2f}, {:.2f})  {:.2e} {:.3f}:  {:.1f}, {:.1f}, "
            "{:.1f}; {:.1f}; {}{}\n",
            100 * worst[k].first, p.sensor.position.x, p.sensor.position.y, p.sensor.position.z, p.sensor.normal.x,
            p.sensor.normal.y, p.sensor.normal.z, patch.area, patch.diameter, luminance(*p.value.indirectVertex),
            luminance(p.value.indirect), luminance(p.value.direct), luminance(run.lighting.solution.indirect[p.patch]),
            run.scene.materials[patch.material].name,
            run.mesh.isCovered(p.patch) ? ", covered" : "");
    }
}

const char* const kUsage =
    "usage: surface_agreement SCENE [points (400)] [key=value ...] [--view | --both] [--solution=FILE.rrs]\n"
    "                         [--csv=FILE]\n"
    "The indirect light an image shows (the mesh) against a final gather at random points on\n"
    "SCENE's surfaces (--view: at the surfaces its camera sees through random pixels; --both:\n"
    "both sets); key=value: scene settings, as with rayrad's --set; --solution: a solution\n"
    "saved by rayrad solve --save for the same scene and settings; --csv: every point.\n";

int agreement(int argc, char** argv) {
    if (argc < 2) {
        std::fputs(kUsage, stderr);
        return 2;
    }
    const std::string sceneFile = argv[1];
    const int count = argc > 2 ? std::atoi(argv[2]) : 400;
    app::PipelineOptions options;
    std::string csvFile;
    options.quiet = true;
    options.wantSensors = false;
    bool onSurfaces = true, inView = false;
    for (int i = 3; i < argc; ++i) {
        const std::string s = argv[i];
        if (s == "--set") continue;  // as rayrad takes them
        if (s == "--view" || s == "--both") {
            inView = true, onSurfaces = s == "--both";
            continue;
        }
        if (s.rfind("--csv=", 0) == 0) {
            csvFile = s.substr(6);
            continue;
        }
        if (s.rfind("--solution=", 0) == 0) {
            options.solutionFile = s.substr(11);
            continue;
        }
        const size_t eq = s.find('=');
        if (eq == std::string::npos) {
            std::fprintf(stderr, "surface_agreement: expected key=value, got \"%s\"\n", argv[i]);
            return 2;
        }
        options.overrides.push_back({s.substr(0, eq), s.substr(eq + 1)});
    }
    const double c0 = processCpuSeconds();
    app::PipelineRun run = app::runPipeline(sceneFile, options);
    const double solveCpu = processCpuSeconds() - c0;
    if (inView && !run.scene.camera) {
        std::fprintf(stderr, "surface_agreement: %s has no camera for --view\n", sceneFile.c_str());
        return 2;
    }
    const radiosity::StageLog log;
    const auto gatherer = radiosity::sensorGatherer(run.scene, run.mesh, *run.embree, run.lighting, log);
    std::vector<PointSet> sets;
    if (onSurfaces) {
        // Points no camera can see are left out before their gathers.
        std::vector<Point> points = samplePoints(run.scene, run.mesh, count);
        const size_t sampled = points.size();
        points.erase(std::remove_if(points.begin(), points.end(),
                                    [&](const Point& p) {
                                        return covered(run.mesh, *run.embree, p.sensor.position, p.sensor.normal);
                                    }),
                     points.end());
        sets.push_back({fmt::format("{} points on the surfaces ({} covered)", sampled, sampled - points.size()),
                        std::move(points)});
    }
    if (inView) {
        int missed = 0;
        std::vector<Point> points = viewPoints(run.scene, run.mesh, *run.embree, count, missed);
        sets.push_back({fmt::format("{} pixels of the camera's view ({} on the sky, a mirror, glass, a lamp or a "
                                    "surface's black back)",
                                    count, missed),
                        std::move(points)});
    }
    for (PointSet& set : sets) evaluate(run, *gatherer, set.points);
    if (!csvFile.empty()) {
        std::FILE* f = std::fopen(csvFile.c_str(), "w");
        if (!f) {
            std::fprintf(stderr, "surface_agreement: cannot write %s\n", csvFile.c_str());
            return 3;
        }
        writeCsv(f, run, sets.back().points);
        std::fclose(f);
    }
    for (const PointSet& set : sets) summarize(sceneFile, run, solveCpu, set);
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    return rayrad::bench::runBench("surface_agreement", kUsage, argc, argv, [&] { return agreement(argc, argv); });
}
