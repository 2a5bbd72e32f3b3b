// Benchmark: the sensor gather on the paper's cube against an independent Monte Carlo
// reference (issue 11, item 4). The cube is convex, so a path tracer needs no visibility:
// from x, cosine-sampled directions hit the walls at y_1, y_2, … and
//   E_ind(x) = Σ_k ρ^k E_dir(y_k),   E_dir(y) = I cosθ / d²   (the cosine and π cancel),
// with the first bounce on Roberts' R2 sequence. Prints, per point, the reference (and how
// far its two independent halves differ), the gathered value and its error, then RMS and
// max over random wall points and over points 1 mm – 0.3 m from an edge or a corner.
// Usage: build/bench/sensor_accuracy [max_edge (0.25: 19 200 triangles)] [random points (24)] [paths (200000)]
#include <app/pipeline.h>
#include <core/random.h>

#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

using namespace rayrad;

namespace {

constexpr double kSide = 10, kIntensity = 50000, kRho = 2.0 / 3.0;
const Vec3 kLight(5, 5, 5);

/// Direct illuminance at wall point y, inward normal n (lx).
double directAt(const Vec3& y, const Vec3& n) {
    Vec3 d = kLight - y;
    double r2 = glm::dot(d, d);
    return kIntensity * glm::dot(n, d) / std::sqrt(r2) / r2;
}

/// The wall hit from x (inside) along unit w: point y and inward normal n.
void hitWall(const Vec3& x, const Vec3& w, Vec3& y, Vec3& n) {
    double best = 1e300, side = 0;
    int axis = 0;
    for (int a = 0; a < 3; ++a) {
        if (w[a] > 1e-15 && (kSide - x[a]) / w[a] < best) best = (kSide - x[a]) / w[a], axis = a, side = kSide;
        if (w[a] < -1e-15 && -x[a] / w[a] < best) best = -x[a] / w[a], axis = a, side = 0;
    }
    y = x + best * w;
    y[axis] = side;
    n = Vec3(0.0);
    n[axis] = side > 0 ? -1 : 1;
}

Vec3 cosineDirection(const Vec3& n, double u1, double u2) {
    Vec3 t = glm::normalize(glm::cross(n, std::abs(n.x) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0)));
    Vec3 b = glm::cross(n, t);
    double r = std::sqrt(u1), phi = 2 * kPi * u2;
    return glm::normalize(r * std::cos(phi) * t + r * std::sin(phi) * b + std::sqrt(std::max(0.0, 1 - u1)) * n);
}

/// E_ind(x) by `paths` random walks; `stream` selects an independent half.
double reference(const Vec3& x0, const Vec3& n0, int paths, uint64_t stream) {
    const double g = 1.32471795724474602596;  // R2 sequence for the first bounce
    Random rng(stream, 11);
    double sum = 0;
    for (int p = 0; p < paths; ++p) {
        Vec3 x = x0, n = n0;
        double w = 1;
        for (int k = 0; w > 1e-7; ++k) {
            double u1 = k == 0 ? std::fmod(0.5 * stream + (p + 1) / g, 1.0) : rng.nextDouble();
            double u2 = k == 0 ? std::fmod(0.5 * stream + (p + 1) / (g * g), 1.0) : rng.nextDouble();
            Vec3 y, ny;
            hitWall(x, cosineDirection(n, u1, u2), y, ny);
            w *= kRho;
            sum += w * directAt(y, ny);
            x = y, n = ny;
        }
    }
    return sum / paths;
}

}  // namespace

int main(int argc, char** argv) {
    const double maxEdge = argc > 1 ? std::atof(argv[1]) : 0.25;
    const int randomPoints = argc > 2 ? std::atoi(argv[2]) : 24;
    const int paths = argc > 3 ? std::atoi(argv[3]) : 200000;
    // Points on the back wall z = 10 (normal −z): random ones, then near an edge and a corner.
    struct Point {
        Vec3 x;
        std::string kind;
    };
    std::vector<Point> points;
    Random rng(2026, 1);
    for (int i = 0; i < randomPoints; ++i)
        points.push_back({Vec3(kSide * rng.nextDouble(), kSide * rng.nextDouble(), kSide), "random"});
    for (double d : {0.001, 0.01, 0.1, 0.3}) {
        points.push_back({Vec3(4.37, d, kSide), fmt::format("edge {} m", d)});
        points.push_back({Vec3(d, d, kSide), fmt::format("corner {} m", d)});
    }
    std::string sensors;
    for (size_t i = 0; i < points.size(); ++i)
        sensors += fmt::format("{}{{\"name\": \"p{}\", \"position\": [{:.17g}, {:.17g}, {:.17g}], \"normal\": [0, 0, -1]}}",
                               i ? ", " : "", i, points[i].x.x, points[i].x.y, points[i].x.z);
    const std::string path = "/tmp/rayrad_bench_sensor_accuracy.json";
    std::ofstream(path) << fmt::format(R"({{"materials": {{"wall": {{"reflectance": 0.6666666666666666}}}},
        "objects": [{{"type": "box", "material": "wall", "min": [0, 0, 0], "max": [10, 10, 10], "facing": "inward"}}],
        "lights": [{{"type": "point", "position": [5, 5, 5], "intensity_cd": 50000}}],
        "sensors": [{}], "radiosity": {{"max_edge": {}}}}})",
                                       sensors, maxEdge);
    app::PipelineOptions options;
    options.quiet = true;
    auto t0 = std::chrono::steady_clock::now();
    auto run = app::runPipeline(path, options);
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    fmt::print("cube, max_edge {} ({} triangles): solve + {} gathers {:.1f} s wall; reference {} paths per point\n",
               maxEdge, run.mesh.patches.size(), points.size(), seconds, 2 * paths);
    fmt::print("{:<14} {:>26} {:>11} {:>9} {:>11} {:>8}\n", "point", "position", "reference", "±halves", "gathered", "error");
    double sumRandom = 0, maxRandom = 0, sumNear = 0, maxNear = 0;
    int nNear = 0;
    // The references, in parallel (each point's two halves have their own streams).
    std::vector<double> halfA(points.size()), halfB(points.size());
    tbb::parallel_for(size_t(0), 2 * points.size(), [&](size_t k) {
        const size_t i = k / 2;
        (k % 2 ? halfB[i] : halfA[i]) = reference(points[i].x, Vec3(0, 0, -1), paths, k % 2 ? 2 : 1);
    });
    for (size_t i = 0; i < points.size(); ++i) {
        double a = halfA[i], b = halfB[i];
        double ref = 0.5 * (a + b), gathered = luminance(run.sensors[i].value.indirect);
        double err = gathered / ref - 1;
        fmt::print("{:<14} {:>26} {:>11.2f} {:>8.3f}% {:>11.2f} {:>+7.3f}%\n", points[i].kind, toString(points[i].x), ref,
                   100 * std::abs(a - b) / ref, gathered, 100 * err);
        if (points[i].kind == "random") sumRandom += err * err, maxRandom = std::max(maxRandom, std::abs(err));
        else sumNear += err * err, maxNear = std::max(maxNear, std::abs(err)), ++nNear;
    }
    fmt::print("random points: RMS {:.3f} %, max {:.3f} %; near edges and corners: RMS {:.3f} %, max {:.3f} %\n",
               100 * std::sqrt(sumRandom / std::max(1, randomPoints)), 100 * maxRandom,
               100 * std::sqrt(sumNear / std::max(1, nNear)), 100 * maxNear);
    return 0;
}
