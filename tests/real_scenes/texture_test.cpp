// Textures: a checker floor and a picture on a wall light the room as the same
// room untextured with each surface at its texture's mean reflectance; the ray tracer shows
// the texture (light and dark checks) without changing the light it reflects on average;
// mesh files bring their texture coordinates and images, and a missing image is a warning.
#include <app/pipeline.h>
#include <tonemap/image_io.h>

#include "pipeline_test_util.h"
#include "test_support.h"

#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <map>

using namespace rayrad;

namespace {

constexpr double kDark = 0.15, kLight = 0.65;  // the checker's linear reflectances

/// A 64 × 64 float checker of 8 × 8 squares (EXR: linear), mean (kDark + kLight) / 2.
std::string writeChecker() {
    HdrImage img(64, 64);
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) img.at(x, y) = Rgb(((x / 8 + y / 8) % 2) ? kLight : kDark);
    const std::string path = "/tmp/rayrad_test_checker.exr";
    tonemap::writeExr(path, img, "checker");
    return path;
}

/// A 48 × 32 "picture" as an 8-bit sRGB PNG: a fine pattern of two colours in 2 × 2 pixel
/// squares, finer than the patches (a pattern that follows the light across patches would
/// change the light, as it should). Returns its path and its mean linear colour.
std::pair<std::string, Rgb> writePicture() {
    std::vector<uint8_t> rgb;
    Rgb sum(0.0);
    auto decode = [](int c) { const double v = c / 255.0; return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4); };
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 48; ++x) {
            const bool first = (x / 2 + y / 2) % 2 == 0;
            const int c[3] = {first ? 200 : 60, first ? 90 : 170, first ? 40 : 120};
            for (int k = 0; k < 3; ++k) rgb.push_back(static_cast<uint8_t>(c[k])), sum[k] += decode(c[k]);
        }
    const std::string path = "/tmp/rayrad_test_picture.png";
    tonemap::writeDisplayImage(path, 48, 32, rgb);
    return {path, sum / (48.0 * 32.0)};
}

std::string room(const std::string& floorMaterial, const std::string& pictureMaterial) {
    return fmt::format(R"({{"materials": {{"wall": {{"reflectance": 0.6}}, "floor": {}, "picture": {}}},
        "objects": [{{"type": "box", "min": [0, 0, 0], "max": [4, 2.8, 3], "facing": "inward", "material": "wall"}},
                    {{"type": "quad", "vertices": [[0, 0.001, 3], [4, 0.001, 3], [4, 0.001, 0], [0, 0.001, 0]], "material": "floor"}},
                    {{"type": "quad", "vertices": [[1, 1, 0.001], [3, 1, 0.001], [3, 2.2, 0.001], [1, 2.2, 0.001]], "material": "picture"}}],
        "lights": [{{"type": "point", "position": [2, 2.6, 1.5], "intensity_cd": 500}}],
        "sensors": [{{"name": "ceiling", "position": [2, 2.8, 1.5], "normal": [0, -1, 0]}},
                    {{"name": "side wall", "position": [0, 1.4, 1.5], "normal": [1, 0, 0]}},
                    {{"name": "front wall", "position": [2, 1.4, 3], "normal": [0, 0, -1]}},
                    {{"name": "floor", "position": [1, 0.001, 1], "normal": [0, 1, 0]}}],
        "camera": {{"position": [2, 2.5, 2.9], "look_at": [2, 0.3, 0.8], "resolution": [80, 60]}},
        "radiosity": {{"max_edge": 0.25}}, "render": {{"spp": 4}}}})",
                       floorMaterial, pictureMaterial);
}

}  // namespace

TEST_CASE("a textured room lights as the same room at the textures' mean reflectances", "[textures]") {
    const std::string checker = writeChecker();
    const auto [picture, pictureMean] = writePicture();
    const std::string textured = room(fmt::format(R"({{"texture": {{"file": "{}", "repeat": [16, 12]}}}})", checker),
                                      fmt::format(R"({{"texture": "{}"}})", picture));
    const std::string plain = room(fmt::format(R"({{"reflectance": {}}})", (kDark + kLight) / 2),
                                   fmt::format(R"({{"reflectance": [{}, {}, {}]}})", pictureMean.r, pictureMean.g, pictureMean.b));
    app::PipelineOptions options = test::quiet();
    options.wantImage = true;
    const auto a = app::runPipeline(test::writeTempScene("textured_room", textured), options);
    const auto b = app::runPipeline(test::writeTempScene("plain_room", plain), options);
    REQUIRE(a.sensors.size() == b.sensors.size());
    REQUIRE(!a.mesh.texturedReflectance.empty());
    // The patches' means average to the textures' means.
    std::map<std::string, std::pair<double, Rgb>> byMaterial;  // area, ∫ρ dA
    for (size_t i = 0; i < a.mesh.patches.size(); ++i) {
        auto& [area, sum] = byMaterial[a.scene.materials[a.mesh.patches[i].material].name];
        area += a.mesh.patches[i].area;
        sum += a.mesh.patches[i].area * Rgb(a.mesh.texturedReflectance[i]);
    }
    const Rgb floorMean = byMaterial["floor"].second / byMaterial["floor"].first;
    const Rgb picMean = byMaterial["picture"].second / byMaterial["picture"].first;
    INFO("floor " << toString(floorMean) << ", picture " << toString(picMean) << " against " << toString(pictureMean));
    CHECK(floorMean.g == Approx((kDark + kLight) / 2).epsilon(0.001));
    for (int c = 0; c < 3; ++c) CHECK(picMean[c] == Approx(pictureMean[c]).epsilon(0.001));
    for (size_t i = 0; i < a.sensors.size(); ++i) {
        const double ta = luminance(a.sensors[i].value.direct + a.sensors[i].value.indirect);
        const double tb = luminance(b.sensors[i].value.direct + b.sensors[i].value.indirect);
        INFO(a.sensors[i].sensor.name << ": textured " << ta << " lx, plain " << tb << " lx");
        CHECK(ta == Approx(tb).epsilon(0.001));
    }

    // The image: on average the same light, but with the checks in it.
    double sumA = 0, sumB = 0, sumDiff = 0;
    const size_t n = a.image->pixels.size();
    for (size_t p = 0; p < n; ++p) {
        const double la = luminance(a.image->pixels[p]), lb = luminance(b.image->pixels[p]);
        sumA += la, sumB += lb, sumDiff += std::abs(la - lb);
    }
    INFO("mean luminance textured " << sumA / n << ", plain " << sumB / n << " cd/m², mean |difference| " << sumDiff / n);
    CHECK(sumA / n == Approx(sumB / n).epsilon(0.02));
    // The checks and the picture show: the pixels differ from the plain room's by 7 % of
    // the mean on average (0 without textures: the same seed), filtered over the pixels.
    CHECK(sumDiff / n > 0.03 * sumB / n);
}

TEST_CASE("a mesh file brings its texture coordinates and image, a missing image is a warning", "[textures]") {
    const std::string checker = writeChecker();
    std::ofstream("/tmp/rayrad_test_tex.mtl") << "newmtl checked\nKd 1 1 1\nmap_Kd rayrad_test_checker.exr\n"
                                                 "newmtl lost\nKd 0.5 0.5 0.5\nmap_Kd no_such_image.png\n";
    std::ofstream("/tmp/rayrad_test_tex.obj") << "mtllib rayrad_test_tex.mtl\n"
                                                 "v 0 0 0\nv 1 0 0\nv 1 0 -1\nv 0 0 -1\nv 0 1 -1\nv 1 1 -1\n"
                                                 "vt 0 0\nvt 4 0\nvt 4 4\nvt 0 4\n"
                                                 "usemtl checked\nf 1/1 2/2 3/3 4/4\n"
                                                 "usemtl lost\nf 4/1 3/2 6/3 5/4\n";
    const std::string json = R"({"objects": [{"type": "mesh", "file": "/tmp/rayrad_test_tex.obj"}],
        "lights": [{"type": "point", "position": [0.5, 0.8, -0.3], "intensity_cd": 10}]})";
    const auto s = app::loadSceneFile(test::writeTempScene("textured_mesh", json), {});
    REQUIRE(s.textures.size() == 1);
    REQUIRE(s.warnings.fileWarnings.size() == 1);
    CHECK(s.warnings.fileWarnings[0].find("no_such_image.png") != std::string::npos);
    int textured = 0;
    for (const auto& g : s.groups)
        if (s.materials[g.material].texture >= 0) {
            ++textured;
            REQUIRE(g.polygonUvs.size() == g.polygons.size());
            CHECK(g.polygonUvs[0].size() == 3);
        }
    CHECK(textured == 1);
    // The patches' means: the checker's mean, (kDark + kLight) / 2, on the textured quad
    // (16 × 16 squares over it: every patch covers many).
    auto run = app::runPipeline(test::writeTempScene("textured_mesh", json), test::quiet({{"radiosity.max_edge", "0.25"}}));
    double area = 0, sum = 0;
    for (size_t i = 0; i < run.mesh.patches.size(); ++i)
        if (run.scene.materials[run.mesh.patches[i].material].texture >= 0)
            area += run.mesh.patches[i].area, sum += run.mesh.patches[i].area * run.mesh.texturedReflectance[i].x;
    CHECK(sum / area == Approx((kDark + kLight) / 2).epsilon(0.01));
}

TEST_CASE("bad textures are named", "[textures]") {
    const std::string base = R"({"materials": {"m": MAT}, "objects": [OBJ],
        "lights": [{"type": "point", "position": [0.5, 0.5, 1], "intensity_cd": 10}]})";
    const std::string quad = R"({"type": "quad", "material": "m", "vertices": [[0,0,0],[1,0,0],[1,1,0],[0,1,0]]})";
    const std::string sphere = R"({"type": "sphere", "material": "m", "center": [0,0,0], "radius": 0.2})";
    auto scene = [&](const std::string& mat, const std::string& obj) {
        std::string s = base;
        s.replace(s.find("MAT"), 3, mat);
        s.replace(s.find("OBJ"), 3, obj);
        return test::writeTempScene("bad_texture", s);
    };
    CHECK_THROWS_WITH(app::loadSceneFile(scene(R"({"texture": "/tmp/no_such_texture.png"})", quad), {}),
                      Catch::Contains("/materials/m/texture: /tmp/no_such_texture.png: no such file"));
    CHECK_THROWS_WITH(app::loadSceneFile(scene(R"({"texture": {"file": "x.png", "repeat": [0, 1]}})", quad), {}),
                      Catch::Contains("/materials/m/texture/repeat"));
    writeChecker();
    CHECK_THROWS_WITH(app::loadSceneFile(scene(R"({"texture": "/tmp/rayrad_test_checker.exr"})", sphere), {}),
                      Catch::Contains("not onto a polygon or a sphere"));
    std::ofstream("/tmp/rayrad_test_not_an_image.png") << "this is not a PNG";
    CHECK_THROWS_WITH(app::loadSceneFile(scene(R"({"texture": "/tmp/rayrad_test_not_an_image.png"})", quad), {}),
                      Catch::Contains("not a texture image OpenImageIO can read"));
}

TEST_CASE("a glTF file's base colour texture and TEXCOORD_0 are used", "[textures]") {
    // tests/data/textured_quad.gltf: a 1 m quad, its texture gltf_checker.png (8-bit, so
    // sRGB-encoded: 0.15 and 0.65 stored as 38 and 166) repeated 4 × 4 times.
    const std::string json = R"({"objects": [{"type": "mesh", "file": ")" + test::sourcePath("tests/data/textured_quad.gltf") +
                             R"("}], "lights": [{"type": "point", "position": [0.5, 0.8, -0.5], "intensity_cd": 10}],
        "radiosity": {"max_edge": 0.1}})";
    auto run = app::runPipeline(test::writeTempScene("textured_gltf", json), test::quiet());
    REQUIRE(run.scene.textures.size() == 1);
    auto decode = [](int c) { const double v = c / 255.0; return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4); };
    const double expected = (decode(38) + decode(166)) / 2;
    double area = 0, sum = 0, lo = 1, hi = 0;
    for (size_t i = 0; i < run.mesh.patches.size(); ++i) {
        area += run.mesh.patches[i].area, sum += run.mesh.patches[i].area * run.mesh.texturedReflectance[i].x;
        lo = std::min(lo, double(run.mesh.texturedReflectance[i].x)), hi = std::max(hi, double(run.mesh.texturedReflectance[i].x));
    }
    INFO("mean " << sum / area << " (patches " << lo << " to " << hi << ") against " << expected);
    CHECK(sum / area == Approx(expected).epsilon(0.005));
    CHECK(hi - lo < 0.1 * expected);  // 0.1 m patches, 3.1 cm checks: every patch near the mean
}

TEST_CASE("a fine checker far away is averaged in linear light (MIP-mapped lookups), not aliased", "[textures]") {
    // An 80 × 40 m floor tiled with 2.5 cm checks of black and white as an 8-bit sRGB PNG
    // (texels 0 and 255: mean 0.5 linear, but 0.21 if the encoded values were averaged),
    // seen from eye height along the floor; a light far above keeps the lighting smooth.
    // Rows where the checks are far smaller than a pixel must show their mean: the same
    // luminance as an untextured floor at ρ = 0.5 × 0.8, and no pixel-to-pixel pattern.
    std::vector<uint8_t> rgb;
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x)
            for (int k = 0; k < 3; ++k) rgb.push_back((x / 8 + y / 8) % 2 ? 255 : 0);
    const std::string checks = "/tmp/rayrad_test_fine_checks.png";
    tonemap::writeDisplayImage(checks, 64, 64, rgb);
    const auto floor = [](const std::string& material) {
        return fmt::format(R"({{"materials": {{"floor": {}}},
            "objects": [{{"type": "quad", "vertices": [[-40, 0, 0], [40, 0, 0], [40, 0, -40], [-40, 0, -40]], "material": "floor"}}],
            "lights": [{{"type": "point", "position": [0, 200, -20], "intensity_cd": 1e6}}],
            "camera": {{"position": [0, 1.6, 0], "look_at": [0, 0.8, -20], "vfov_deg": 40, "resolution": [160, 120]}},
            "radiosity": {{"max_edge": 4}}, "render": {{"spp": 4}}}})",
                           material);
    };
    // 80 m / 400 repeats of 8 checks: 2.5 cm checks.
    const std::string textured = floor(fmt::format(R"({{"reflectance": 0.8, "texture": {{"file": "{}", "repeat": [400, 200]}}}})", checks));
    app::PipelineOptions options = test::quiet();
    options.wantImage = true;
    const auto a = app::runPipeline(test::writeTempScene("fine_checks", textured), options);
    const auto b = app::runPipeline(test::writeTempScene("fine_checks_plain", floor(R"({"reflectance": 0.4})")), options);
    // The far floor: rows 62–72 (the floor's far edge is at the image centre, row 60: 14 to
    // 30 m away, where a pixel spans 3 to 7 checks across and far more along), columns 40–120.
    double sumA = 0, sumB = 0, steps = 0;
    int count = 0;
    for (int y = 62; y <= 72; ++y)
        for (int x = 40; x < 120; ++x) {
            const double la = luminance(a.image->at(x, y)), lb = luminance(b.image->at(x, y));
            REQUIRE(lb > 0);
            sumA += la, sumB += lb, ++count;
            steps += std::abs(la - luminance(a.image->at(x + 1, y))) / lb;  // neighbour to neighbour
        }
    INFO("far floor: textured " << sumA / count << " cd/m², plain " << sumB / count << " cd/m², mean |step| "
                                << 100 * steps / count << " % of the plain floor");
    CHECK(sumA / count == Approx(sumB / count).epsilon(0.03));
    CHECK(steps / count < 0.05);
}
