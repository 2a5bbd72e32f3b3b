// Benchmark: the sensor gather on the paper's cube against an independent Monte Carlo
// reference (the path tracer is tests/cube_path_tracer.h). Prints the
// points near an edge and a corner one by one (reference, how far its two independent
// halves differ, gathered value, error), then RMS and max over random points on all six
// walls (the ten worst listed), and the time of the solve and the gathers.
// Usage: build/bench/sensor_accuracy [max_edge (0.25: 19 200 triangles)] [random points (24)]
//        [paths per half (200000)] [gather_refine_levels (scene default, -1)] [key=value ...]
//        (the last: scene settings, as with --set, e.g. radiosity.gather_min_weight=0)
//        build/bench/sensor_accuracy [max_edge] grid[:K] [paths per half] [key=value ...]
//        (a K x K grid, default 32, at the cell centres of the back wall: the grid's error
//        and the sensor stage's CPU seconds against the solve's, then the outer ring of
//        cells beside the side walls run alone, where the corner and midpoint re-gathers
//        are)
#include "bench_main.h"

#include <app/pipeline.h>
#include <core/random.h>

#include "cube_path_tracer.h"

#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <string>
#include <vector>

using namespace rayrad;
namespace cube = rayrad::test::cube;

namespace {

double cpuSeconds() {
    return static_cast<double>(std::clock()) / CLOCKS_PER_SEC;
}

struct Point {
    Vec3 x, n;
    std::string kind;
};

/// Scene settings given as key=value arguments from argv[first] on; false on a bad one.
bool addSettings(int argc, char** argv, int first, app::PipelineOptions& options) {
    for (int i = first; i < argc; ++i) {
        const std::string setting = argv[i];
        const size_t eq = setting.find('=');
        if (eq == std::string::npos) {
            std::fprintf(stderr, "sensor_accuracy: expected key=value, got \"%s\"\n", argv[i]);
            return false;
        }
        options.overrides.push_back({setting.substr(0, eq), setting.substr(eq + 1)});
    }
    return true;
}

/// A k x k grid at the cell centres of the back wall z = 10, as a designer places one:
/// its error against the path tracer, and what its sensor stage costs against the solve.
/// On that wall the cube is symmetric under x <-> 10 - x, y <-> 10 - y and x <-> y, so
/// about k²/8 distinct points need a reference.
int gridMode(double maxEdge, int k, int paths, int argc, char** argv, int firstSetting) {
    app::PipelineOptions options;
    options.quiet = true;
    if (!addSettings(argc, argv, firstSetting, options)) return 2;
    // A sensor on the back wall facing into the cube, appended to a scene's sensor list.
    auto addSensor = [](std::string& list, const std::string& name, const Vec3& x) {
        list += fmt::format(
            "{}{{\"name\": \"{}\", \"position\": [{:.17g}, {:.17g}, {:.17g}], "
            "\"normal\": [0, 0, -1]}}",
            list.empty() ? "" : ", ", name, x.x, x.y, x.z);
    };
    std::vector<Vec3> points;
    std::string sensors;
    for (int j = 0; j < k; ++j)
        for (int i = 0; i < k; ++i) {
            const Vec3 x((i + 0.5) * cube::kSide / k, (j + 0.5) * cube::kSide / k, cube::kSide);
            addSensor(sensors, fmt::format("g{}_{}", i, j), x);
            points.push_back(x);
        }
    const std::string path = "/tmp/rayrad_bench_sensor_grid.json";
    std::ofstream(path) << cube::scene(sensors, maxEdge);
    auto run = app::runPipeline(path, options);
    auto sensorStage = [](const app::PipelineRun& r) {
        for (const auto& stage : r.report.stages())
            if (stage.name.rfind("sensors", 0) == 0) return std::make_pair(stage.cpuSeconds, stage.seconds);
        return std::make_pair(0.0, 0.0);
    };
    const auto [sensorCpu, sensorWall] = sensorStage(run);
    // Where the cost is: the outer ring of cells (beside the side walls) on its own.
    std::string ring;
    size_t ringCount = 0;
    for (int j = 0; j < k; ++j)
        for (int i = 0; i < k; ++i) {
            if (i != 0 && j != 0 && i != k - 1 && j != k - 1) continue;
            addSensor(ring, fmt::format("r{}_{}", i, j), points[static_cast<size_t>(j * k + i)]);
            ++ringCount;
        }
    std::ofstream(path) << cube::scene(ring, maxEdge);
    const auto ringRun = app::runPipeline(path, options);
    const double ringCpu = sensorStage(ringRun).first;
    const double solveCpu = run.report.totalCpuSeconds() - sensorCpu;
    // The distinct points (canonical: x <= y <= 5), each traced once with both halves.
    auto canonical = [&](const Vec3& x) {
        double a = std::min(x.x, cube::kSide - x.x), b = std::min(x.y, cube::kSide - x.y);
        return std::make_pair(std::min(a, b), std::max(a, b));
    };
    std::vector<std::pair<double, double>> distinct;
    for (const Vec3& x : points) distinct.push_back(canonical(x));
    std::sort(distinct.begin(), distinct.end());
    distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
    std::vector<double> halfA(distinct.size()), halfB(distinct.size());
    tbb::parallel_for(size_t(0), 2 * distinct.size(), [&](size_t q) {
        const size_t i = q / 2;
        const Vec3 x(distinct[i].first, distinct[i].second, cube::kSide);
        (q % 2 ? halfB[i] : halfA[i]) = cube::indirectReference(x, Vec3(0, 0, -1), paths, q % 2 ? 2 : 1);
    });
    double sum2 = 0, sum = 0, worst = 0, spread2 = 0;
    Vec3 worstAt(0.0);
    for (size_t i = 0; i < points.size(); ++i) {
        const size_t d = static_cast<size_t>(std::lower_bound(distinct.begin(), distinct.end(), canonical(points[i])) -
                                             distinct.begin());
        const double ref = 0.5 * (halfA[d] + halfB[d]);
        const double err = luminance(run.sensors[i].value.indirect) / ref - 1;
        sum += err, sum2 += err * err;
        if (std::abs(err) > std::abs(worst)) worst = err, worstAt = points[i];
    }
    for (size_t i = 0; i < distinct.size(); ++i) {
        const double s = (halfA[i] - halfB[i]) / (halfA[i] + halfB[i]);  // half the halves' relative difference
        spread2 += s * s;
    }
    const double n = static_cast<double>(points.size());
    fmt::print(
        "cube, max_edge {} ({} triangles): {} x {} grid on the back wall, {} distinct references of 2 x {} "
        "paths (their mean is good to {:.3f} % RMS)\n",
        maxEdge, run.mesh.patches.size(), k, k, distinct.size(), paths,
        100 * std::sqrt(spread2 / static_cast<double>(distinct.size())));
    fmt::print("gathered indirect against the reference: RMS {:.3f} %, mean {:+.3f} %, max {:+.3f} % at {}\n",
               100 * std::sqrt(sum2 / n), 100 * sum / n, 100 * worst, toString(worstAt));
    fmt::print("solve {:.2f} CPU-s; sensor stage {:.2f} CPU-s ({:.2f} s wall, {} gathers): {:.2f} x the solve\n",
               solveCpu, sensorCpu, sensorWall, run.lighting.sensorGathers, sensorCpu / solveCpu);
    fmt::print(
        "the outer ring of cells alone, beside the side walls ({} sensors, a run of its own): "
        "{:.2f} CPU-s, {} gathers\n",
        ringCount, ringCpu, ringRun.lighting.sensorGathers);
    return 0;
}

const char* const kUsage =
    "usage: sensor_accuracy [max_edge (0.25: 19 200 triangles)] [random points (24)] [paths per half (200000)]\n"
    "                       [gather_refine_levels (scene default, -1)] [key=value ...]\n"
    "       sensor_accuracy [max_edge] grid[:K] [paths per half] [key=value ...]\n"
    "The sensor gather on the paper's cube against a path tracer: points near an edge and a\n"
    "corner, then random points on all six walls (RMS, max); grid[:K]: a K x K grid (32) on\n"
    "the back wall, its error and the sensor stage's CPU seconds against the solve's.\n";

int accuracy(int argc, char** argv) {
    const double maxEdge = argc > 1 ? std::atof(argv[1]) : 0.25;
    if (argc > 2 && std::string(argv[2]).rfind("grid", 0) == 0) {
        const std::string arg = argv[2];
        const int k = arg.size() > 5 && arg[4] == ':' ? std::atoi(arg.c_str() + 5) : 32;
        if (k < 1) {
            std::fprintf(stderr, "sensor_accuracy: grid:K needs K >= 1, got \"%s\"\n", argv[2]);
            return 2;
        }
        return gridMode(maxEdge, k, argc > 3 ? std::atoi(argv[3]) : 200000, argc, argv, 4);
    }
    const int randomPoints = argc > 2 ? std::atoi(argv[2]) : 24;
    const int paths = argc > 3 ? std::atoi(argv[3]) : 200000;
    const int refineLevels = argc > 4 ? std::atoi(argv[4]) : -1;
    // Near an edge and a corner of the back wall z = 10 (normal −z), then random points.
    std::vector<Point> points;
    for (double d : {0.001, 0.01, 0.1, 0.3}) {
        points.push_back({Vec3(4.37, d, cube::kSide), Vec3(0, 0, -1), fmt::format("edge {} m", d)});
        points.push_back({Vec3(d, d, cube::kSide), Vec3(0, 0, -1), fmt::format("corner {} m", d)});
    }
    const size_t nearCount = points.size();
    Random rng(2026, 1);
    for (int i = 0; i < randomPoints; ++i) {
        int axis = static_cast<int>(rng.nextDouble() * 3) % 3;
        bool far = rng.nextDouble() < 0.5;
        Vec3 x(cube::kSide * rng.nextDouble(), cube::kSide * rng.nextDouble(), cube::kSide * rng.nextDouble());
        Vec3 n(0.0);
        x[axis] = far ? cube::kSide : 0;
        n[axis] = far ? -1 : 1;
        points.push_back({x, n, "random"});
    }
    std::string sensors;
    for (size_t i = 0; i < points.size(); ++i)
        sensors += fmt::format(
            "{}{{\"name\": \"p{}\", \"position\": [{:.17g}, {:.17g}, {:.17g}], \"normal\": [{}, {}, {}]}}",
            i ? ", " : "", i, points[i].x.x, points[i].x.y, points[i].x.z, points[i].n.x, points[i].n.y, points[i].n.z);
    const std::string path = "/tmp/rayrad_bench_sensor_accuracy.json";
    std::ofstream(path) << cube::scene(sensors, maxEdge);
    app::PipelineOptions options;
    options.quiet = true;
    if (refineLevels >= 0)
        options.overrides.push_back({"radiosity.gather_refine_levels", std::to_string(refineLevels)});
    if (!addSettings(argc, argv, 5, options)) return 2;
    auto t0 = std::chrono::steady_clock::now();
    double c0 = cpuSeconds();
    auto run = app::runPipeline(path, options);
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    double cpu = cpuSeconds() - c0;
    double gatherSeconds = 0;
    for (const auto& stage : run.report.stages())
        if (stage.name.rfind("sensors", 0) == 0) gatherSeconds = stage.seconds;
    fmt::print(
        "cube, max_edge {} ({} triangles), gather_refine_levels {}: solve + {} gathers {:.1f} s wall, {:.1f} "
        "CPU-s (gathers {:.1f} s wall); reference 2 x {} paths per point\n",
        maxEdge, run.mesh.patches.size(), run.scene.gather.gatherRefineLevels, points.size(), seconds, cpu,
        gatherSeconds, paths);
    // The references, in parallel (each point's two halves have their own streams).
    std::vector<double> halfA(points.size()), halfB(points.size());
    tbb::parallel_for(size_t(0), 2 * points.size(), [&](size_t k) {
        const size_t i = k / 2;
        (k % 2 ? halfB[i] : halfA[i]) = cube::indirectReference(points[i].x, points[i].n, paths, k % 2 ? 2 : 1);
    });
    struct Row {
        size_t i;
        double ref, spread, gathered, err;
    };
    std::vector<Row> rows;
    for (size_t i = 0; i < points.size(); ++i) {
        double ref = 0.5 * (halfA[i] + halfB[i]), gathered = luminance(run.sensors[i].value.indirect);
        rows.push_back({i, ref, std::abs(halfA[i] - halfB[i]) / ref, gathered, gathered / ref - 1});
    }
    auto print = [&](const Row& r) {
        fmt::print("{:<14} {:>36} {:>11.2f} {:>8.3f}% {:>11.2f} {:>+7.3f}%\n", points[r.i].kind,
                   toString(points[r.i].x), r.ref, 100 * r.spread, r.gathered, 100 * r.err);
    };
    fmt::print("{:<14} {:>36} {:>11} {:>9} {:>11} {:>8}\n", "point", "position", "reference", "±halves", "gathered",
               "error");
    double sumNear = 0, maxNear = 0, sumRandom = 0, maxRandom = 0, sumSpread = 0;
    for (const Row& r : rows) {
        bool near = r.i < nearCount;
        (near ? sumNear : sumRandom) += r.err * r.err;
        double& worst = near ? maxNear : maxRandom;
        worst = std::max(worst, std::abs(r.err));
        if (!near) sumSpread += r.spread * r.spread;
        if (near || randomPoints <= 50) print(r);
    }
    if (randomPoints > 50) {
        std::vector<Row> random(rows.begin() + static_cast<long>(nearCount), rows.end());
        std::sort(random.begin(), random.end(),
                  [](const Row& a, const Row& b) { return std::abs(a.err) > std::abs(b.err); });
        fmt::print("the ten worst random points:\n");
        for (size_t k = 0; k < 10 && k < random.size(); ++k) print(random[k]);
    }
    fmt::print("near edges and corners: RMS {:.3f} %, max {:.3f} %\n", 100 * std::sqrt(sumNear / nearCount),
               100 * maxNear);
    if (randomPoints > 0)
        fmt::print("{} random points: RMS {:.3f} %, max {:.3f} % (reference halves differ by {:.3f} % RMS)\n",
                   randomPoints, 100 * std::sqrt(sumRandom / randomPoints), 100 * maxRandom,
                   100 * std::sqrt(sumSpread / randomPoints));
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    return rayrad::bench::runBench("sensor_accuracy", kUsage, argc, argv, [&] { return accuracy(argc, argv); });
}
