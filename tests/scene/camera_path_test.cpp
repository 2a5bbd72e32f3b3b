// Walkthrough paths: frames start and end at the first and last keyframe, pass
// through every keyframe reached at its time, move at an even pace, and bad paths are named.
#include <scene/camera_path.h>
#include <scene/scene.h>

#include "scene_test_util.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace rayrad;

namespace {

scene::Camera key(Vec3 position, Vec3 lookAt) {
    scene::Camera c;
    c.position = position;
    c.lookAt = lookAt;
    c.width = 32;
    c.height = 24;
    return c;
}

double distance(const Vec3& a, const Vec3& b) { return glm::length(a - b); }

}  // namespace

TEST_CASE("a straight walk: frames at an even pace from the first keyframe to the last", "[scene]") {
    // Three collinear keyframes, unevenly spaced (1 m then 3 m), the view along the walk.
    const std::vector<scene::Camera> keys = {key({0, 1, 0}, {0, 1, -10}), key({0, 1, -1}, {0, 1, -11}),
                                             key({0, 1, -4}, {0, 1, -14})};
    const auto frames = scene::framesAlongPath(keys, 9);
    REQUIRE(frames.size() == 9);
    CHECK(distance(frames.front().position, keys.front().position) < 1e-12);
    CHECK(distance(frames.back().position, keys.back().position) < 1e-12);
    // Total motion 4 m in 8 steps: frame 2 is at keyframe 1 (t = 1 m), and every step is
    // 0.5 m along the line within the spline's wobble.
    CHECK(distance(frames[2].position, keys[1].position) < 1e-12);
    for (size_t k = 1; k < frames.size(); ++k) {
        const double step = distance(frames[k].position, frames[k - 1].position);
        CHECK(step == Approx(0.5).epsilon(0.15));
        CHECK(std::abs(frames[k].position.x) < 1e-12);
    }
    CHECK(frames[4].width == 32);
    CHECK(frames[4].height == 24);
}

TEST_CASE("turning on the spot: the view turns, the position stays", "[scene]") {
    const std::vector<scene::Camera> keys = {key({1, 1, 1}, {1, 1, 0}), key({1, 1, 1}, {0, 1, 1}), key({1, 1, 1}, {1, 1, 2})};
    const auto frames = scene::framesAlongPath(keys, 5);
    for (const auto& f : frames) CHECK(distance(f.position, {1, 1, 1}) < 1e-12);
    // Keyframe 1 (a 90° turn of 180°) is frame 2; its view direction is the keyframe's.
    const Vec3 d = glm::normalize(frames[2].lookAt - frames[2].position);
    CHECK(distance(d, {-1, 0, 0}) < 1e-9);
}

TEST_CASE("a field of view zooms linearly between keyframes", "[scene]") {
    auto a = key({0, 0, 0}, {0, 0, -1}), b = key({0, 0, -1}, {0, 0, -2});
    a.verticalFovDeg = 40;
    b.verticalFovDeg = 60;
    const auto frames = scene::framesAlongPath({a, b}, 3);
    CHECK(frames[1].verticalFovDeg > 40);
    CHECK(frames[1].verticalFovDeg < 60);
    CHECK(frames[2].verticalFovDeg == Approx(60));
}

TEST_CASE("bad camera paths are named", "[scene]") {
    const std::string base = test::boxScene();
    const auto withPath = [&](const std::string& path) {
        return base.substr(0, base.size() - 1) + R"(, "camera_path": )" + path + "}";
    };
    CHECK(test::parseErrors(withPath(R"({"frames": 10, "keyframes": [{"position": [0.5,0.5,0.5], "look_at": [0,0.5,0.5]}]})"))
              .contains("/camera_path/keyframes: a path needs at least 2 keyframes, got 1"));
    CHECK(test::parseErrors(withPath(R"({"frames": 1, "keyframes": []})")).contains("/camera_path/frames"));
    CHECK(test::parseErrors(withPath(R"({"keyframes": []})")).contains("/camera_path: missing required key \"frames\""));
    CHECK(test::parseErrors(withPath(R"({"frames": 3, "keyframes": [{"position": [0.5,0.5,0.5]}, {"position": [0.5,0.5,0.4], "look_at": [0,0.5,0.5]}]})"))
              .contains("/camera_path/keyframes/0: missing required key \"look_at\""));
    CHECK(test::parseErrors(withPath(R"({"frames": 3, "keyframes": [{"position": [0.5,0.5,0.5], "look_at": [0,0.5,0.5], "resolution": [8, 8]}, {"position": [0.5,0.5,0.4], "look_at": [0,0.5,0.5]}]})"))
              .contains("/camera_path/keyframes/0/resolution"));
    // A path that does not move is refused when the scene is built, at the path.
    const auto still = scene::parseScene(
        withPath(R"({"frames": 3, "keyframes": [{"position": [0.5,0.5,0.5], "look_at": [0,0.5,0.5]}, {"position": [0.5,0.5,0.5], "look_at": [0,0.5,0.5]}]})"),
        "test.json", {});
    CHECK_THROWS_WITH(scene::buildScene(still), Catch::Contains("/camera_path: the keyframes do not move"));
    // A good one: its frames, in the scene.
    const auto good = scene::parseScene(
        withPath(R"({"frames": 4, "resolution": [16, 8], "keyframes": [{"position": [0.5,0.5,0.9], "look_at": [0.5,0.5,0]}, {"position": [0.5,0.5,0.3], "look_at": [0.5,0.5,0]}]})"),
        "test.json", {});
    const auto s = scene::buildScene(good);
    REQUIRE(s.pathFrames.size() == 4);
    CHECK(s.pathFrames[3].position.z == Approx(0.3));
    CHECK(s.pathFrames[0].width == 16);
}
