// item 4: sensors right at any position. The gather on the paper's cube at
// 19 200 triangles against the test's own Monte Carlo reference (cube_path_tracer.h):
// 1 mm – 0.1 m from an edge or a corner within 0.3 % (default run), and hundreds of
// random positions on all six walls with RMS ≤ 0.1 %, max ≤ 0.5 % (label `accuracy`,
// a few minutes: ctest -L accuracy).
#include <app/pipeline.h>
#include <core/random.h>

#include "cube_path_tracer.h"
#include "pipeline_test_util.h"
#include "test_support.h"

#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

using namespace rayrad;

namespace {

struct WallPoint {
    Vec3 x, n;
};

/// Gathered indirect illuminance (lx) at the points, and each one's relative error
/// against the mean of two independent reference estimates of `paths` walks.
std::vector<double> gatherErrors(const std::vector<WallPoint>& points, int paths, const std::string& name) {
    std::string sensors;
    for (size_t i = 0; i < points.size(); ++i)
        sensors += fmt::format("{}{{\"name\": \"p{}\", \"position\": [{:.17g}, {:.17g}, {:.17g}], \"normal\": [{}, {}, {}]}}",
                               i ? ", " : "", i, points[i].x.x, points[i].x.y, points[i].x.z, points[i].n.x,
                               points[i].n.y, points[i].n.z);
    auto run = app::runPipeline(test::writeTempScene(name, test::cube::scene(sensors, 0.25)), test::quiet());
    REQUIRE(run.mesh.patches.size() == 19200);
    REQUIRE(run.sensors.size() == points.size());
    std::vector<double> reference(2 * points.size());
    tbb::parallel_for(size_t(0), reference.size(), [&](size_t k) {
        reference[k] = test::cube::indirectReference(points[k / 2].x, points[k / 2].n, paths, 1 + k % 2);
    });
    std::vector<double> errors;
    for (size_t i = 0; i < points.size(); ++i) {
        double ref = 0.5 * (reference[2 * i] + reference[2 * i + 1]);
        errors.push_back(luminance(run.sensors[i].value.indirect) / ref - 1);
    }
    return errors;
}

/// On the back wall z = 10 (normal −z): d from the edge y = 0 (at x = 4.37), and d from
/// both edges x = 0 and y = 0 (toward the corner).
std::vector<WallPoint> nearEdgesAndCorners(const std::vector<double>& distances) {
    std::vector<WallPoint> points;
    for (double d : distances) {
        points.push_back({Vec3(4.37, d, 10), Vec3(0, 0, -1)});
        points.push_back({Vec3(d, d, 10), Vec3(0, 0, -1)});
    }
    return points;
}

}  // namespace

TEST_CASE("cube, 19 200 triangles: the gather 1 mm to 0.1 m from an edge or a corner is within 0.3 % of a path tracer",
          "[real_scenes]") {
    const std::vector<double> distances = {0.001, 0.01, 0.1};
    auto errors = gatherErrors(nearEdgesAndCorners(distances), 100000, "cube_near_edges");
    for (size_t i = 0; i < errors.size(); ++i) {
        INFO((i % 2 ? "corner " : "edge ") << distances[i / 2] << " m: error " << 100 * errors[i] << " %");
        CHECK(std::abs(errors[i]) < 3e-3);
    }
}

TEST_CASE("cube, 19 200 triangles: the gather at 300 random wall positions has RMS <= 0.1 % and max <= 0.5 %",
          "[accuracy]") {
    // Random points on all six walls (inward normals), then the near-edge set.
    std::vector<WallPoint> points;
    Random rng(2026, 7);
    for (int i = 0; i < 300; ++i) {
        int axis = static_cast<int>(rng.nextDouble() * 3) % 3;
        bool far = rng.nextDouble() < 0.5;
        Vec3 x(test::cube::kSide * rng.nextDouble(), test::cube::kSide * rng.nextDouble(),
               test::cube::kSide * rng.nextDouble());
        Vec3 n(0.0);
        x[axis] = far ? test::cube::kSide : 0;
        n[axis] = far ? -1 : 1;
        points.push_back({x, n});
    }
    auto errors = gatherErrors(points, 100000, "cube_random_points");
    double sum = 0, worst = 0;
    size_t at = 0;
    for (size_t i = 0; i < errors.size(); ++i) {
        sum += errors[i] * errors[i];
        if (std::abs(errors[i]) > worst) worst = std::abs(errors[i]), at = i;
    }
    double rms = std::sqrt(sum / errors.size());
    INFO("RMS " << 100 * rms << " %, max " << 100 * worst << " % at " << toString(points[at].x));
    CHECK(rms <= 1e-3);
    CHECK(worst <= 5e-3);
}
