// Luminaires from photometric files in scenes: the direct light follows the
// file's table in the luminaire's frame, the flux is the table's integral (or flux_lm),
// and the indirect light inside a closed sphere is the analytic ρ/(1−ρ) Φ/A.
#include <app/light_group_parts.h>
#include <app/pipeline.h>
#include <core/colour_temperature.h>
#include <core/input_error.h>
#include <radiosity/direct/direct_light.h>
#include <radiosity/form_factors/form_factor.h>
#include <radiosity/solution/energy_balance.h>
#include <scene/light_groups.h>
#include <scene/photometry.h>
#include <scene/scene_parser.h>

#include "pipeline_test_util.h"
#include "test_support.h"

#include <fmt/format.h>
#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>

using namespace rayrad;
using test::quiet;

namespace {

double kNearFieldSizes() {
    return scene::kNearFieldSizes;
}

const std::string kIes = test::sourcePath("tests/data/luminaires/radiance_examp1.ies");

/// A closed sphere (radius 1, reflectance rho) with one luminaire at the centre; sensors
/// at the nadir (A), sideways along C0 (B) and along C90 (C).
std::string sphereWithLuminaire(double rho, const std::string& luminaire) {
    return fmt::format(R"({{"materials": {{"m": {{"reflectance": {}}}}},
        "objects": [{{"type": "sphere", "material": "m", "radius": 1, "subdivisions": 12, "facing": "inward"}}],
        "lights": [{{"type": "luminaire", "position": [0, 0, 0], {}}}],
        "sensors": [{{"name": "A", "position": [0, -1, 0], "normal": [0, 1, 0]}},
                    {{"name": "B", "position": [0.70710678, -0.70710678, 0], "normal": [-0.70710678, 0.70710678, 0]}},
                    {{"name": "C", "position": [0, -0.70710678, 0.70710678], "normal": [0, 0.70710678, -0.70710678]}}],
        "radiosity": {{"max_edge": 10, "stop_unshot": 1e-5}}}})",
                       rho, luminaire);
}

}  // namespace

TEST_CASE("a luminaire in a closed sphere: direct light from its table, indirect rho/(1-rho) Phi/A", "[luminaire]") {
    const double rho = 0.5;
    // A point source (its 1.2 m opening would make the sphere its near field).
    const std::string json = sphereWithLuminaire(
        rho, fmt::format(R"("file": "{}", "aim": [0, -1, 0], "c0_toward": [1, 0, 0], "point_source": true)", kIes));
    auto run = app::runPipeline(test::writeTempScene("luminaire_sphere", json), quiet());
    const scene::Photometry web = scene::readPhotometry(kIes);
    const double flux = web.integratedFlux();
    REQUIRE(run.lighting.lights->emittedFlux() == Approx(flux).epsilon(1e-12));
    // Direct: I(γ, C) at distance 1 on the sphere, normal toward the centre (cos = 1).
    const double expectedDirect[3] = {web.intensity(0, 0), web.intensity(45, 0), web.intensity(45, 90)};
    const double expectedIndirect = rho / (1 - rho) * flux / run.mesh.totalArea();
    for (size_t i = 0; i < 3; ++i) {
        const auto& s = run.sensors[i];
        INFO(s.sensor.name);
        CHECK(luminance(s.value.direct) == Approx(expectedDirect[i]).epsilon(1e-6));    // sensor positions to 8 digits
        CHECK(luminance(s.value.indirect) == Approx(expectedIndirect).epsilon(0.015));  // as for a point light
    }
    CHECK(expectedDirect[1] != Approx(expectedDirect[2]).epsilon(0.01));  // the table does differ by azimuth
    // The energy account holds with a strongly directional source.
    const auto balance = app::energyBalanceOf(run);
    CHECK(std::abs(balance.relativeError()) < 5e-4);
}

TEST_CASE("luminaire orientation, flux, dimming and maintenance", "[luminaire]") {
    auto direct = [&](const std::string& fields) {
        const std::string json =
            sphereWithLuminaire(0.0, fmt::format(R"("file": "{}", "point_source": true, {})", kIes, fields));
        auto run = app::runPipeline(test::writeTempScene("luminaire_options", json), quiet());
        std::vector<double> out;
        for (const auto& s : run.sensors) out.push_back(luminance(s.value.direct));
        return out;
    };
    const auto base = direct(R"("c0_toward": [1, 0, 0])");
    // C0 turned to +z: what C lit before, B now gets, and the reverse.
    const auto turned = direct(R"("c0_toward": [0, 0, 1])");
    CHECK(turned[1] == Approx(base[2]).epsilon(1e-9));
    CHECK(turned[2] == Approx(base[1]).epsilon(1e-9));
    // Aimed up: the nadir sensor gets what γ = 180° sends.
    const scene::Photometry web = scene::readPhotometry(kIes);
    const auto up = direct(R"("aim": [0, 5, 0])");
    CHECK(up[0] == Approx(web.intensity(180, 0)).epsilon(1e-9));
    // DIALux-style rotations about the scene's x, y, z axes of the luminaire at rest
    // (down, C0 along +x): 90° about y turns C0 to −z; 90° about z turns the axis to +x
    // and C0 to +y.
    CHECK(direct(R"("rotation_deg": [0, 0, 0])") == base);
    const auto aboutY = direct(R"("rotation_deg": [0, 90, 0])");
    const auto c0minusZ = direct(R"("c0_toward": [0, 0, -1])");
    const auto aboutZ = direct(R"("rotation_deg": [0, 0, 90])");
    const auto sideways = direct(R"("nadir": [1, 0, 0], "c0_toward": [0, 1, 0])");
    for (size_t i = 0; i < 3; ++i) {
        CHECK(aboutY[i] == Approx(c0minusZ[i]).epsilon(1e-9));
        CHECK(aboutZ[i] == Approx(sideways[i]).epsilon(1e-9));
    }
    CHECK(aboutY[1] == Approx(base[2]).epsilon(1e-9));  // C0 now where C90 was: sensor B gets C90's light
    // flux_lm scales the table; dimming and maintenance multiply.
    const auto scaled = direct(R"("flux_lm": 1000, "dimming": 0.5, "maintenance_factor": 0.8)");
    CHECK(scaled[0] == Approx(base[0] * 1000 / web.integratedFlux() * 0.5 * 0.8).epsilon(1e-9));
}

TEST_CASE("a type B floodlight file lights the sphere by its H and V angles", "[luminaire]") {
    // I = 300 + H + 2 V (degrees) on H, V in ±90.
    std::string cd;
    for (int h = -90; h <= 90; h += 45)
        for (int v = -90; v <= 90; v += 45) cd += std::to_string(300 + h + 2 * v) + " ";
    const std::string ies =
        "IESNA:LM-63-2002\n[TEST] type B\nTILT=NONE\n1 -1 1 5 5 2 2 0 0 0\n1 1 10\n"
        "-90 -45 0 45 90\n-90 -45 0 45 90\n" +
        cd + "\n";
    const std::string scratch = test::writeTempScene("type_b_ies", "{}");
    const std::string iesPath = scratch.substr(0, scratch.find_last_of('/')) + "/flood_b.ies";
    std::ofstream(iesPath) << ies;
    const std::string json =
        sphereWithLuminaire(0.0, fmt::format(R"("file": "{}", "point_source": true, "c0_toward": [1, 0, 0])", iesPath));
    auto run = app::runPipeline(test::writeTempScene("luminaire_type_b", json), quiet());
    // A: the nadir, H = V = 0. B: 45° toward C0 (+x), H = 45. C: 45° toward +z, which is
    // −C90 (C90 = up × C0 = −z): V = −45.
    const double expected[3] = {300, 300 + 45, 300 - 90};
    for (size_t i = 0; i < 3; ++i) {
        INFO(run.sensors[i].sensor.name);
        CHECK(luminance(run.sensors[i].value.direct) == Approx(expected[i]).epsilon(1e-6));
    }
}

TEST_CASE("an isotropic photometric file lights a room as a point light of the same intensity", "[luminaire]") {
    std::string v;
    for (int a = 0; a <= 180; a += 5) v += std::to_string(a) + " ";
    std::string c;
    for (int i = 0; i < 37; ++i) c += "250 ";
    const std::string ies =
        "IESNA:LM-63-2002\n[TEST] isotropic\nTILT=NONE\n1 -1 1 37 1 1 2 0 0 0\n1 1 10\n" + v + "\n0\n" + c + "\n";
    const std::string path = test::writeTempScene("isotropic_ies", "{}");  // a scratch path
    const std::string iesPath = path.substr(0, path.find_last_of('/')) + "/isotropic.ies";
    std::ofstream(iesPath) << ies;
    auto room = [&](const std::string& light) {
        const std::string json = fmt::format(R"({{"materials": {{"w": {{"reflectance": 0.6}}}},
            "objects": [{{"type": "box", "min": [0, 0, 0], "max": [3, 2.5, 4], "facing": "inward", "material": "w"}},
                        {{"type": "box", "min": [1, 0, 1], "max": [2, 0.8, 2], "material": "w"}}],
            "lights": [{}],
            "sensors": [{{"name": "floor", "position": [0.5, 0, 3], "normal": [0, 1, 0]}},
                        {{"name": "wall", "position": [3, 1.2, 2], "normal": [-1, 0, 0]}},
                        {{"name": "shadow", "position": [1.5, 0, 2.3], "normal": [0, 1, 0]}}],
            "radiosity": {{"max_edge": 0.5}}}})",
                                             light);
        return app::runPipeline(test::writeTempScene("isotropic_room", json), quiet());
    };
    auto point = room(R"({"type": "point", "position": [1.4, 2.2, 1.7], "intensity_cd": 250})");
    auto luminaire =
        room(fmt::format(R"({{"type": "luminaire", "position": [1.4, 2.2, 1.7], "file": "{}"}})", iesPath));
    REQUIRE(point.sensors.size() == luminaire.sensors.size());
    for (size_t i = 0; i < point.sensors.size(); ++i) {
        INFO(point.sensors[i].sensor.name);
        CHECK(luminance(luminaire.sensors[i].value.direct) ==
              Approx(luminance(point.sensors[i].value.direct)).epsilon(1e-9));
        CHECK(luminance(luminaire.sensors[i].value.indirect) ==
              Approx(luminance(point.sensors[i].value.indirect)).epsilon(1e-6));
    }
}

TEST_CASE("a colour temperature gives a light of luminance 1, white near 6500 K", "[luminaire]") {
    const Rgb d65 = colourOfTemperature(6504);
    CHECK(luminance(d65) == Approx(1.0));
    // The Planckian locus at 6504 K lies a little below D65 in y (D65 is greener): its RGB
    // has a little more red and blue than green.
    CHECK(d65.r == Approx(1.0).margin(0.05));
    CHECK(d65.b == Approx(1.0).margin(0.05));
    CHECK(d65.g < 1.0);
    const Rgb warm = colourOfTemperature(2700);
    CHECK(luminance(warm) == Approx(1.0));
    CHECK(warm.r > warm.g);
    CHECK(warm.g > warm.b);
}

TEST_CASE("bad luminaires are named", "[luminaire]") {
    auto error = [&](const std::string& fields) {
        try {
            app::runPipeline(test::writeTempScene("bad_luminaire", sphereWithLuminaire(0.5, fields)), quiet());
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    CHECK(error(R"("file": "nothere.ies")").find("/lights/0/file: ") != std::string::npos);
    CHECK(error(R"("file": "nothere.ies")").find("no such file") != std::string::npos);
    CHECK(error(fmt::format(R"("file": "{}", "dimming": 0)", kIes))
              .find("/lights/0/dimming: expected a factor in (0, 1]") != std::string::npos);
    CHECK(error(fmt::format(R"("file": "{}", "aim": [0, 0, 0])", kIes))
              .find("/lights/0/aim: the luminaire's axis must not be zero") != std::string::npos);
    CHECK(error(fmt::format(R"("file": "{}", "c0_toward": [0, -2, 0])", kIes))
              .find("/lights/0/c0_toward: the C0 direction must not be parallel") != std::string::npos);
    CHECK(error(fmt::format(R"("file": "{}", "cct_k": 500)", kIes))
              .find("/lights/0/cct_k: expected a colour temperature") != std::string::npos);
    CHECK(error(fmt::format(R"("file": "{}", "rotation_deg": [0, 90, 0], "aim": [0, -1, 0])", kIes))
              .find("/lights/0/aim: give either \"rotation_deg\" or \"aim\"") != std::string::npos);
    CHECK(error(fmt::format(R"("file": "{}", "rotation_deg": [0, 90])", kIes)).find("/lights/0/rotation_deg: ") !=
          std::string::npos);
    CHECK(error(fmt::format(R"("file": "{}", "intensity_cd": 5)", kIes)).find("/lights/0/intensity_cd: unknown key") !=
          std::string::npos);
}

TEST_CASE("a luminaire's mirror image sends the intensity the real luminaire sends along the reflected path",
          "[luminaire][mirrors]") {
    // A mirror on the floor (y = 0, facing up) and a luminaire aimed sideways: its image
    // below the floor lights a receiver above through the mirror with the intensity the
    // real luminaire sends toward the mirror point.
    const std::string json = fmt::format(
        R"({{"materials": {{"w": {{"reflectance": 0.5}}, "m": {{"type": "mirror", "specular_reflectance": 1}}}},
        "objects": [{{"type": "quad", "material": "m", "vertices": [[-5, 0, -5], [-5, 0, 5], [5, 0, 5], [5, 0, -5]]}},
                    {{"type": "quad", "material": "w", "vertices": [[-5, 4, -5], [5, 4, -5], [5, 4, 5], [-5, 4, 5]]}}],
        "lights": [{{"type": "luminaire", "file": "{}", "position": [0, 2, 0], "aim": [1, 1.5, 0.3], "c0_toward": [0, 0, 1]}}]}})",
        kIes);
    const scene::Scene s = scene::buildScene(scene::parseScene(json, "mirror_luminaire.json"));
    const radiosity::DirectLight lights(s);
    REQUIRE(lights.imageCount() == 1);
    const size_t image = lights.sourceCount() - 1;  // the image of point source 0
    REQUIRE(lights.isPointSource(image));
    struct NoOccluders : Visibility {
        bool visible(const Vec3&, const Vec3&) const override { return true; }
    } open;
    int lit = 0;
    for (const Vec3 x : {Vec3(1, 3, 0.5), Vec3(-2, 3.9, 1), Vec3(0.3, 1, -2), Vec3(2, 1, 1)}) {
        const Vec3 n(0, -1, 0);
        const Vec3 d = lights.pointSourcePosition(image) - x;
        const double geometry = std::abs(glm::dot(n, d)) / glm::length(d) / glm::dot(d, d);  // cosθ / r²
        const double e = luminance(lights.fromPointSource(image, x, n, open));
        INFO("x " << toString(x));
        const double intensity = luminance(lights.pointSourceIntensityToward(image, x));
        CHECK(e == Approx(intensity * geometry).epsilon(1e-9).margin(1e-12));
        lit += e > 0;
    }
    CHECK(lit >= 2);
}

TEST_CASE("the same luminaire as EULUMDAT and as IES gives the same light", "[luminaire]") {
    // The CIE 190 example luminaire (sample_11.ldt) written out as an IES LM-63-2002 file
    // with its table in absolute candela: the two readers must agree.
    const std::string ldt = test::sourcePath("tests/data/luminaires/eulumdatugr_sample_11.ldt");
    const scene::Photometry p = scene::readPhotometry(ldt);
    std::string ies =
        fmt::format("IESNA:LM-63-2002\n[TEST] sample_11 as IES\nTILT=NONE\n1 -1 1 {} {} 1 2 {} {} {}\n1 1 10\n",
                    p.vertical.size(), p.horizontal.size(), p.width, p.length, p.height);
    for (double v : p.vertical) ies += fmt::format("{:.17g} ", v);
    ies += "\n";
    for (double h : p.horizontal) ies += fmt::format("{:.17g} ", h);
    ies += "\n";
    for (const auto& plane : p.candela) {
        for (double cd : plane) ies += fmt::format("{:.17g} ", cd);
        ies += "\n";
    }
    const std::string iesPath = "/tmp/rayrad_test_sample_11.ies";
    std::ofstream(iesPath) << ies;
    const scene::Photometry q = scene::readPhotometry(iesPath);
    CHECK(q.integratedFlux() == Approx(p.integratedFlux()).epsilon(1e-12));
    for (double gamma : {0.0, 12.5, 47.0, 89.0, 120.0})
        for (double c : {0.0, 33.0, 90.0, 181.0, 287.5})
            CHECK(q.intensity(gamma, c) == Approx(p.intensity(gamma, c)).epsilon(1e-12));
    auto sensors = [&](const std::string& file) {
        const std::string json = sphereWithLuminaire(0.5, fmt::format(R"("file": "{}", "c0_toward": [0, 0, 1])", file));
        return app::runPipeline(test::writeTempScene("ldt_vs_ies", json), quiet()).sensors;
    };
    const auto a = sensors(ldt), b = sensors(iesPath);
    for (size_t i = 0; i < a.size(); ++i) {
        CHECK(luminance(b[i].value.direct) == Approx(luminance(a[i].value.direct)).epsilon(1e-9));
        CHECK(luminance(b[i].value.indirect) == Approx(luminance(a[i].value.indirect)).epsilon(1e-9));
    }
}

TEST_CASE("light groups: each group's part, scaled, gives what a re-solve with the group dimmed gives",
          "[luminaire][groups]") {
    auto room = [&](double dimB, const std::string& solver) {
        return fmt::format(
            R"({{"materials": {{"w": {{"reflectance": 0.6}}, "lamp": {{"type": "emissive", "luminance_cd_m2": 2000, "group": "panel"}}}},
            "objects": [{{"type": "box", "min": [0, 0, 0], "max": [4, 2.8, 5], "facing": "inward", "material": "w"}},
                        {{"type": "box", "min": [1, 0, 1], "max": [2.5, 0.75, 2], "material": "w"}},
                        {{"type": "quad", "material": "lamp", "vertices": [[3, 2.79, 4], [3.5, 2.79, 4], [3.5, 2.79, 4.5], [3, 2.79, 4.5]]}}],
            "lights": [{{"type": "luminaire", "file": "{0}", "position": [1, 2.7, 1.5], "group": "A"}},
                       {{"type": "luminaire", "file": "{0}", "position": [3, 2.7, 2.5], "group": "B", "dimming": {1}}},
                       {{"type": "point", "position": [2, 2, 4], "intensity_cd": 80}}],
            "work_planes": [{{"name": "wp", "outline": [[0, 0], [4, 0], [4, 5], [0, 5]], "height": 0.8, "border": 0.5}}],
            {2}}})",
            kIes, dimB, solver);
    };
    // How far the groups' parts, scaled, are from a re-solve with B at 30 %.
    auto check = [&](const std::string& solver, double sumBound, double dimBound) {
        const std::string file = test::writeTempScene("groups_full", room(1.0, solver));
        const auto options = quiet();
        const auto full = app::runPipeline(file, options);
        const auto groups = scene::lightGroups(full.scene);
        REQUIRE(groups == std::vector<std::string>{"", "A", "B", "panel"});  // "" the ungrouped point light
        const auto parts = app::solveLightGroups(file, options, full, groups);
        CHECK(app::largestGroupSumDifference(full.sensors, parts) < sumBound);
        // The re-solve with the full solve's ΔI_max, as the groups' solves.
        auto dimmedOptions =
            quiet({{"clusters.max_illuminance_step_lx", fmt::format("{:.17g}", full.lighting.maxIlluminanceStep)}});
        const auto dimmed = app::runPipeline(test::writeTempScene("groups_dimmed", room(0.3, solver)), dimmedOptions);
        double worst = 0;
        for (size_t i = 0; i < full.sensors.size(); ++i) {
            double predicted = 0;
            for (size_t g = 0; g < groups.size(); ++g)
                predicted +=
                    (groups[g] == "B" ? 0.3 : 1.0) * luminance(parts.parts[g][i].direct + parts.parts[g][i].indirect);
            const double resolved = luminance(dimmed.sensors[i].value.direct + dimmed.sensors[i].value.indirect);
            worst = std::max(worst, std::abs(predicted / resolved - 1));
        }
        INFO(solver << ": largest difference " << 100 * worst << " %");
        CHECK(worst < dimBound);
    };
    // Without clusters the transfers do not depend on the light: the parts add up exactly
    // (to the stopping tolerance).
    check(R"("radiosity": {"max_edge": 0.4, "stop_unshot": 1e-6}, "clusters": {"enabled": false})", 1e-5, 1e-5);
    // With clusters, a dimmer group's shots are refined less, relative to its own light:
    // the sum stays within the solve's own discretisation (measured 0.25 % here, 0.10 % in
    // the office scene).
    check(R"("radiosity": {"max_edge": 0.4})", 5e-3, 5e-3);
}

TEST_CASE("near a luminaire its light leaves from the whole opening: a Lambertian square against pi L F",
          "[luminaire]") {
    // A 0.6 m square opening with the far-field distribution of a Lambertian emitter,
    // I(γ) = L A cos γ: within five sizes of it the illuminance is the area source's,
    // E = π L F (the analytic form factor); beyond, the point source's I cos θ / d².
    const double side = 0.6, L = 1000, I0 = L * side * side;
    std::string v, c;
    for (int a = 0; a <= 180; a += 5) {
        v += std::to_string(a) + " ";
        c += fmt::format("{:.17g} ", a <= 90 ? I0 * std::cos(a * kPi / 180) : 0.0);
    }
    const std::string ies = fmt::format(
        "IESNA:LM-63-2002\n[TEST] Lambertian square\nTILT=NONE\n1 -1 1 37 1 1 2 {} {} 0\n1 1 10\n{}\n0\n{}\n", side,
        side, v, c);
    const std::string iesPath = "/tmp/rayrad_test_lambertian.ies";
    std::ofstream(iesPath) << ies;
    const double heights[] = {0.3, 0.6, 1.2, 2.5, 4.0};
    std::string sensors;
    for (size_t i = 0; i < 5; ++i)
        sensors += fmt::format("{}{{\"name\": \"h{}\", \"position\": [0.1, {}, 0.05], \"normal\": [0, 1, 0]}}",
                               i ? ", " : "", i, 5.0 - heights[i]);
    const std::string json = fmt::format(R"({{"materials": {{"black": {{"reflectance": 0}}}},
        "objects": [{{"type": "quad", "material": "black", "vertices": [[-20, 0, -20], [-20, 0, 20], [20, 0, 20], [20, 0, -20]]}}],
        "lights": [{{"type": "luminaire", "file": "{}", "position": [0, 5, 0], "aim": [0, 0, 0], "c0_toward": [1, 0, 0]}}],
        "sensors": [{}], "radiosity": {{"max_edge": 10}}}})",
                                         iesPath, sensors);
    auto run = app::runPipeline(test::writeTempScene("near_field", json), quiet());
    const scene::Photometry web = scene::readPhotometry(iesPath);  // the table as bilinear as rayrad reads it
    const Vec3 square[4] = {{-0.3, 5, -0.3}, {0.3, 5, -0.3}, {0.3, 5, 0.3}, {-0.3, 5, 0.3}};  // facing down
    for (size_t i = 0; i < 5; ++i) {
        const Vec3 x(0.1, 5.0 - heights[i], 0.05);
        const double areaSource = kPi * L * radiosity::formFactorToPolygon(x, Vec3(0, 1, 0), square, 4, Vec3(0, -1, 0));
        const Vec3 d = Vec3(0, 5, 0) - x;
        const double r = glm::length(d), cosg = d.y / r;
        const double gamma = std::acos(cosg) * 180 / kPi;
        const double pointSource = web.intensity(gamma, std::atan2(-x.z, x.x) * 180 / kPi) * cosg / (r * r);
        const double got = luminance(run.sensors[i].value.direct);
        INFO("height " << heights[i] << ": got " << got << ", area source " << areaSource << ", point source "
                       << pointSource);
        if (heights[i] < kNearFieldSizes() * side)
            CHECK(got == Approx(areaSource).epsilon(0.02));
        else
            CHECK(got == Approx(pointSource).epsilon(1e-9));
    }
}
