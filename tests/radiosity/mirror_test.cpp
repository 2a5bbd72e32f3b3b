// Mirrors: the image method (virtual lights and shooters), its analytic references, and
// the ray tracer's view of a room with a wall mirror.
#include <core/random.h>
#include <radiosity/mirrors/mirror_images.h>
#include <scene/polygon.h>
#include "solved_scene.h"

#include "scene/scene_test_util.h"
#include "test_support.h"

#include <fmt/format.h>

#include <cmath>

using namespace rayrad;

TEST_CASE("closed diffuse sphere: uniform indirect rho/(1-rho) Phi/A for rho 0.3 0.7 0.9", "[solver][mirrors]") {
    double rho = GENERATE(0.3, 0.7, 0.9);
    // A true sphere gives every point E_ind = ρ/(1−ρ) Φ / A. On the tessellation the
    // point values at the sensors agree within 1.5 % with A the polyhedron's area.
    std::string json = test::closedSphereScene(rho, 12, R"("max_edge": 10, "stop_unshot": 1e-5)");
    auto run = test::solve(test::writeTempScene(fmt::format("sphere_rho_{}", rho), json));
    REQUIRE(run.lighting.clustering.multiPatchClusters() > 0);
    double expected = rho / (1 - rho) * 4 * kPi * 100 / run.mesh.totalArea();
    for (const auto& s : run.sensors) {
        INFO("rho " << rho << " sensor " << s.sensor.name << " gathered " << luminance(s.value.indirect) << " expected "
                    << expected);
        CHECK(luminance(s.value.indirect) == Approx(expected).epsilon(0.015));
    }
}

TEST_CASE("SPH2 and SPH4: total illuminance at the paper's points within the paper's errors", "[solver][mirrors]") {
    // Table 4 references (method.md); the paper's 768-triangle sphere cut to a half and a
    // quarter. Paper errors: SPH2 within 2.3 %, SPH4 within 6.5 %; direct light exact.
    for (auto [file, bound] :
         {std::pair{"scenes/sphere/sph2.json", 0.023}, std::pair{"scenes/sphere/sph4.json", 0.065}}) {
        auto run = test::solve(test::sourcePath(file));
        REQUIRE(run.lighting.mirrorImages() > 0);
        REQUIRE(!run.sensors.empty());
        for (const auto& s : run.sensors) {
            double total = luminance(s.value.direct + s.value.indirect);
            INFO(file << " " << s.sensor.name << " total " << total << " reference " << *s.sensor.refTotal);
            CHECK(luminance(s.value.direct) == Approx(*s.sensor.refDirect).epsilon(1e-4));
            CHECK(total == Approx(*s.sensor.refTotal).epsilon(bound));
        }
    }
}

TEST_CASE("two facing mirrors: images of images stop at the depth and weight limits", "[mirrors]") {
    auto mirror = [](double x, double nx, double ks) {
        scene::Mirror m;  // CCW seen from the side the normal points to
        if (nx < 0)
            m.polygon = {{x, 0, 0}, {x, 0, 1}, {x, 1, 1}, {x, 1, 0}};
        else
            m.polygon = {{x, 0, 0}, {x, 1, 0}, {x, 1, 1}, {x, 0, 1}};
        m.normal = {nx, 0, 0};
        m.offset = nx * x;
        m.specular = Rgb(ks);
        return m;
    };
    std::vector<scene::Mirror> facing = {mirror(0, 1, 0.9), mirror(2, -1, 0.9)};
    // Each chain alternates between the two mirrors: two chains per depth, cut at the depth.
    bool truncated = false;
    CHECK(radiosity::enumerateMirrorImages(facing, {4, 1e-3}, &truncated).size() == 8);
    CHECK(truncated);
    // 0.9^k >= 1e-3 for k <= 65: the weight stops them before a depth of 1000.
    auto deep = radiosity::enumerateMirrorImages(facing, {1000, 1e-3});
    CHECK(deep.size() == 2 * 65);
    for (const auto& image : deep) CHECK(luminance(image.weight) >= 1e-3);
    // Back to back, neither mirror sees the other: no images of images.
    std::vector<scene::Mirror> backToBack = {mirror(0, -1, 0.9), mirror(2, 1, 0.9)};
    CHECK(radiosity::enumerateMirrorImages(backToBack, {8, 1e-3}, &truncated).size() == 2);
    CHECK_FALSE(truncated);
}

namespace {
/// A 90° mirror corner: the floor z = 0 (front +z) and the wall y = 0 (front +y),
/// 1 m × 1 m, sharing the x edge, Ks 0.9.
std::vector<scene::Mirror> mirrorCorner() {
    scene::Mirror floor, wall;
    floor.polygon = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    floor.normal = {0, 0, 1};
    wall.polygon = {{0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0}};
    wall.normal = {0, 1, 0};
    floor.specular = wall.specular = Rgb(0.9);
    return {floor, wall};
}
/// A point drawn uniformly in the ball of radius r about c (rejection from the cube).
Vec3 uniformInBall(Random& rng, const Vec3& c, double r) {
    Vec3 d;
    do d = Vec3(rng.nextDouble(), rng.nextDouble(), rng.nextDouble()) * 2.0 - 1.0;
    while (glm::dot(d, d) > 1);
    return c + r * d;
}
}  // namespace

TEST_CASE("a 90-degree mirror corner: light meets each mirror at most once, so the chains end", "[mirrors]") {
    bool truncated = true;
    auto images = radiosity::enumerateMirrorImages(mirrorCorner(), {8, 1e-3}, &truncated);
    // (floor), (wall), (floor, wall), (wall, floor): after two reflections the light
    // moves away from both planes.
    CHECK(images.size() == 4);
    CHECK_FALSE(truncated);
    for (const auto& image : images) CHECK(image.chain.size() <= 2);
}

TEST_CASE("segment-to-polygon distance: crossings, faces, edges", "[mirrors]") {
    const std::vector<Vec3> square = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    const Vec3 n(0, 0, 1);
    CHECK(scene::segmentPolygonDistance({0.5, 0.5, -1}, {0.5, 0.5, 1}, square, n) == 0);             // crosses
    CHECK(scene::segmentPolygonDistance({0.5, 0.5, 2}, {0.2, 0.3, 0.5}, square, n) == Approx(0.5));  // over the face
    CHECK(scene::segmentPolygonDistance({2, 0.5, -1}, {2, 0.5, 1}, square, n) == Approx(1));         // beside an edge
    CHECK(scene::segmentPolygonDistance({1.3, 1.4, 0}, {1.3, 1.4, 0}, square, n) == Approx(0.5));    // off a corner
    CHECK(scene::segmentDistance({0, 0, 0}, {1, 0, 0}, {0.5, -1, 1}, {0.5, 1, 1}) == Approx(1));
}

TEST_CASE("MirrorImage::mayPass never rejects two balls between which light passes through the chain", "[mirrors]") {
    // The 90° corner's chain (floor, wall): random balls in image space and receivers in
    // front of the wall; wherever a sampled pair of points inside the balls sees through
    // both apertures (throughApertures), mayPass must say the balls may exchange light.
    const std::vector<scene::Mirror> mirrors = mirrorCorner();
    auto images = radiosity::enumerateMirrorImages(mirrors, {8, 1e-3});
    Random rng(7);
    auto inBall = [&](const Vec3& c, double r) { return uniformInBall(rng, c, r); };
    int passing = 0, rejected = 0;
    for (const auto& image : images) {
        for (int trial = 0; trial < 300; ++trial) {
            // A ball of the real scene above the floor, in front of the wall, and its image.
            const Vec3 source(3 * rng.nextDouble() - 1, 2 * rng.nextDouble(), 2 * rng.nextDouble());
            const Vec3 receiver(3 * rng.nextDouble() - 1, 2 * rng.nextDouble(), 2 * rng.nextDouble());
            const double rs = 0.3 * rng.nextDouble(), rr = trial % 2 ? 0.0 : 0.3 * rng.nextDouble();
            const Vec3 imageCentre = image.point(source);
            bool sees = false;
            for (int k = 0; k < 200 && !sees; ++k)
                sees = radiosity::throughApertures(mirrors, image, inBall(imageCentre, rs), inBall(receiver, rr));
            const bool may = image.mayPass(imageCentre, rs, receiver, rr);
            if (sees) {
                INFO("chain length " << image.chain.size() << " image ball " << toString(imageCentre) << " r " << rs
                                     << " receiver " << toString(receiver) << " r " << rr);
                CHECK(may);
                ++passing;
            }
            rejected += !may;
        }
    }
    // Both cases occur, so the check above is not vacuous and the test does cull.
    CHECK(passing > 50);
    CHECK(rejected > 100);
}

TEST_CASE("MirrorImage::mayPassToPoint never rejects a ball that a receiver point sees through the chain",
          "[mirrors]") {
    // The 90° corner's chains, and a thin strip (a mirror's bevel, 5 cm wide) with
    // receivers close above it, where the cone from the point culls what the segment's
    // distance cannot. Wherever a sampled point of the image ball is seen from the
    // receiver through every aperture (throughApertures), mayPassToPoint must say so; it
    // must also cull more than mayPass does for a point.
    scene::Mirror strip;
    strip.polygon = {{0, 0, 0}, {2, 0, 0}, {2, 0.05, 0}, {0, 0.05, 0}};
    strip.normal = {0, 0, 1};
    strip.specular = Rgb(0.9);
    Random rng(13);
    auto inBall = [&](const Vec3& c, double r) { return uniformInBall(rng, c, r); };
    int passing = 0, rejected = 0, rejectedBySegment = 0;
    for (const std::vector<scene::Mirror>& mirrors : {mirrorCorner(), std::vector<scene::Mirror>{strip}}) {
        const bool thin = mirrors.size() == 1;
        for (const auto& image : radiosity::enumerateMirrorImages(mirrors, {8, 1e-3})) {
            for (int trial = 0; trial < 600; ++trial) {
                const Vec3 source(3 * rng.nextDouble() - 0.5, 2 * rng.nextDouble() - (thin ? 1 : 0),
                                  2 * rng.nextDouble());
                const Vec3 receiver(3 * rng.nextDouble() - 0.5, 2 * rng.nextDouble() - (thin ? 1 : 0),
                                    (thin ? 0.3 : 2) * rng.nextDouble());
                const double r = 0.5 * rng.nextDouble();
                const Vec3 imageCentre = image.point(source);
                bool sees = false;
                for (int k = 0; k < 400 && !sees; ++k)
                    sees = radiosity::throughApertures(mirrors, image, inBall(imageCentre, r), receiver);
                const bool may = image.mayPassToPoint(imageCentre, r, receiver);
                if (sees) {
                    INFO("chain length " << image.chain.size() << " image ball " << toString(imageCentre) << " r " << r
                                         << " receiver " << toString(receiver));
                    CHECK(may);
                    ++passing;
                }
                rejected += !may;
                rejectedBySegment += !image.mayPass(imageCentre, r, receiver, 0);
            }
        }
    }
    CHECK(passing > 100);
    CHECK(rejected > rejectedBySegment);
}

TEST_CASE("Mirror::facedBy never rejects a surface point that light reaches through the chain", "[mirrors]") {
    // The 90° corner's chain: random surface points (position, unit normal) in front of
    // the wall and random points of the images; wherever the straight line from the
    // surface point to an image point passes the apertures and leaves the point's front
    // hemisphere, the chain's last mirror must count as faced (the shooting and the
    // gather skip a chain whose end a surface does not face).
    const std::vector<scene::Mirror> mirrors = mirrorCorner();
    auto images = radiosity::enumerateMirrorImages(mirrors, {8, 1e-3});
    Random rng(11);
    auto direction = [&] {
        Vec3 d;
        do d = Vec3(rng.nextDouble(), rng.nextDouble(), rng.nextDouble()) * 2.0 - 1.0;
        while (glm::dot(d, d) > 1 || glm::dot(d, d) < 1e-6);
        return glm::normalize(d);
    };
    int reached = 0, notFaced = 0;
    for (const auto& image : images) {
        const scene::Mirror& last = mirrors[image.chain.back()];
        for (int trial = 0; trial < 2000; ++trial) {
            const Vec3 x(3 * rng.nextDouble() - 1, 2 * rng.nextDouble(), 2 * rng.nextDouble());
            const Vec3 n = direction();
            const Vec3 source(3 * rng.nextDouble() - 1, 2 * rng.nextDouble(), 2 * rng.nextDouble());
            const Vec3 imagePoint = image.point(source);
            const bool faced = last.facedBy(x, n);
            notFaced += !faced;
            if (glm::dot(n, imagePoint - x) > 0 && radiosity::throughApertures(mirrors, image, imagePoint, x)) {
                INFO("chain length " << image.chain.size() << " point " << toString(x) << " normal " << toString(n));
                CHECK(faced);
                ++reached;
            }
        }
    }
    CHECK(reached > 100);
    CHECK(notFaced > 1000);
}

TEST_CASE("a room between two facing mirrors solves and stays finite", "[mirrors][stability]") {
    std::string json =
        R"({"materials": {"w": {"reflectance": 0.5}, "m": {"type": "mirror", "specular_reflectance": 0.95}},
        "objects": [{"type": "box", "min": [0, 0, 0], "max": [3, 2, 2], "facing": "inward", "material": "w"},
                    {"type": "quad", "material": "m", "vertices": [[0.01, 0.5, 0.5], [0.01, 1.5, 0.5], [0.01, 1.5, 1.5], [0.01, 0.5, 1.5]]},
                    {"type": "quad", "material": "m", "vertices": [[2.99, 0.5, 0.5], [2.99, 0.5, 1.5], [2.99, 1.5, 1.5], [2.99, 1.5, 0.5]]}],
        "lights": [{"type": "point", "position": [1.5, 1.8, 1], "intensity_cd": 100}],
        "sensors": [{"name": "floor", "position": [1.5, 0, 1], "normal": [0, 1, 0]}],
        "radiosity": {"max_edge": 0.5, "mirror_depth": 6}})";
    auto run = test::solve(test::writeTempScene("facing_mirrors", json));
    CHECK(run.lighting.mirrorImages() == 12);
    CHECK(run.lighting.solution.converged);
    for (const auto& s : run.sensors) {
        CHECK(std::isfinite(luminance(s.value.indirect)));
        CHECK(luminance(s.value.indirect) > 0);
    }
}
