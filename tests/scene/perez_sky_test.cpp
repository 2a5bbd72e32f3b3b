// The Perez all-weather sky: the 1990 indices and efficacies, the 1993 distribution, and
// the sky a scene gets from one hour's weather.
#include <app/validate_daylight.h>
#include <scene/daylight/perez.h>
#include <scene/scene_parser.h>

#include "test_support.h"

#include <cmath>

using namespace rayrad;

namespace {

/// A scene's daylight from the JSON of its "daylight" block (a quad to light).
scene::Daylight daylightOf(const std::string& daylight) {
    const std::string json = R"({"materials": {"m": {"reflectance": 0.5}},
        "objects": [{"type": "quad", "material": "m", "vertices": [[0,0,0],[1,0,0],[1,1,0],[0,1,0]]}],
        "daylight": )" + daylight + "}";
    return *scene::parseScene(json, "t.json").daylight;
}

std::string refused(const std::string& daylight) {
    try {
        daylightOf(daylight);
    } catch (const std::exception& e) {
        return e.what();
    }
    return {};
}

}  // namespace

TEST_CASE("perez: clearness and brightness follow Perez 1990 eqs. 1 and 2", "[daylight]") {
    // Sun 30° from the zenith on 1 January; D = 100, I = 700 W/m².
    const double z = kPi / 6;
    const auto s = scene::perezFromIrradiance(700, 100, {z, 1, 11});
    const double k = 1.041 * z * z * z;
    CHECK(s.clearness == Approx((800.0 / 100 + k) / (1 + k)).epsilon(1e-12));
    const double airMass = 1 / (std::cos(z) + 0.15 * std::pow(93.885 - 30, -1.253));
    const double extraterrestrial = 1367 * (1.00011 + 0.034221 + 0.000719);  // Spencer on day 1
    CHECK(s.brightness == Approx(100 * airMass / extraterrestrial).epsilon(1e-9));
    CHECK(s.bin == 7);  // ε ≈ 7.5: the clearest bin
}

TEST_CASE("perez: efficacies of a clear and an overcast hour are those daylight has", "[daylight]") {
    // Clear: D 100 W/m², I 800 W/m², sun 40° from the zenith. Overcast: D 150, I 0.
    const auto clear = scene::perezFromIrradiance(800, 100, {40 * kPi / 180, 172, 11});
    const auto overcast = scene::perezFromIrradiance(0, 150, {50 * kPi / 180, 172, 11});
    CHECK(overcast.bin == 0);
    // Perez 1990 reports the diffuse efficacy between about 100 and 140 lm/W, the beam's about 90–110.
    CHECK(clear.diffuseHorizontalIlluminance / 100 > 100);
    CHECK(clear.diffuseHorizontalIlluminance / 100 < 150);
    CHECK(clear.directNormalIlluminance / 800 > 85);
    CHECK(clear.directNormalIlluminance / 800 < 115);
    CHECK(overcast.diffuseHorizontalIlluminance / 150 > 100);
    CHECK(overcast.diffuseHorizontalIlluminance / 150 < 140);
    CHECK(overcast.directNormalIlluminance == 0);
}

TEST_CASE("perez: an hour given as illuminances finds the irradiances back", "[daylight]") {
    for (const auto& [direct, diffuse, zenithDeg] : {std::tuple{800.0, 100.0, 40.0}, {300.0, 200.0, 60.0},
                                                     {50.0, 250.0, 30.0}, {0.0, 80.0, 75.0}}) {
        const scene::PerezConditions c{zenithDeg * kPi / 180, 100, 11};
        const auto byIrradiance = scene::perezFromIrradiance(direct, diffuse, c);
        const auto byIlluminance = scene::perezFromIlluminance(byIrradiance.directNormalIlluminance,
                                                               byIrradiance.diffuseHorizontalIlluminance, c);
        INFO(direct << ", " << diffuse << " at " << zenithDeg << "°");
        CHECK(byIlluminance.diffuseHorizontalIrradiance == Approx(diffuse).margin(0.5));
        CHECK(byIlluminance.directNormalIrradiance == Approx(direct).margin(0.5));
        CHECK(byIlluminance.bin == byIrradiance.bin);
    }
}

TEST_CASE("perez: a scene's Perez sky sends its diffuse illuminance onto a horizontal plane", "[daylight]") {
    for (const std::string& hour : {std::string(R"("direct_normal_irradiance": 750, "diffuse_horizontal_irradiance": 110)"),
                                    std::string(R"("direct_normal_irradiance": 0, "diffuse_horizontal_irradiance": 180)"),
                                    std::string(R"("direct_normal_illuminance": 30000, "diffuse_horizontal_illuminance": 25000)")}) {
        const auto d = daylightOf(R"({"up": [0,0,1], "north": [0,1,0], "sky": {"type": "perez", )" + hour +
                                  R"(}, "sun": {"latitude": 48.1, "longitude": 11.6, "utc_offset": 2, "date": "2026-06-21", "time": "15:00"}})");
        REQUIRE(d.perez);
        INFO(hour << ": ε " << d.perez->clearness << ", Δ " << d.perez->brightness);
        CHECK(app::skyOnHorizontalPlane(d) == Approx(d.perez->diffuseHorizontalIlluminance).epsilon(1e-3));
        CHECK(d.sunNormalIlluminance == Approx(d.perez->directNormalIlluminance));
    }
}

TEST_CASE("perez: its shape: overcast brighter at the zenith, clear brightest by the sun", "[daylight]") {
    const std::string sun = R"("sun": {"altitude": 35, "azimuth": 180})";
    const auto overcast = daylightOf(
        R"({"up": [0,0,1], "north": [0,1,0], "sky": {"type": "perez", "direct_normal_irradiance": 0, "diffuse_horizontal_irradiance": 150}, )" +
        sun + "}");
    const auto clear = daylightOf(
        R"({"up": [0,0,1], "north": [0,1,0], "sky": {"type": "perez", "direct_normal_irradiance": 800, "diffuse_horizontal_irradiance": 90}, )" +
        sun + "}");
    const Vec3 zenith(0, 0, 1), northHorizon(0, 1, 0.02);
    // Overcast (ε ≈ 1): about the CIE overcast sky, zenith 2–4 × the horizon, no matter the azimuth.
    const double ratio = overcast.luminance(zenith) / overcast.luminance(glm::normalize(northHorizon));
    CHECK(ratio > 1.5);
    CHECK(ratio < 4);
    // Clear: 10° from the sun far brighter than the zenith; the darkest part about 90° from the sun.
    const double alt = 35 * kPi / 180;
    const Vec3 nearSun(0, -std::cos(alt + 0.17), std::sin(alt + 0.17));
    const Vec3 opposite(0, std::cos(kPi / 2 - alt), std::sin(kPi / 2 - alt));  // 90° from the sun, through the zenith
    CHECK(clear.luminance(glm::normalize(nearSun)) > 3 * clear.luminance(zenith));
    CHECK(clear.luminance(glm::normalize(opposite)) < clear.luminance(zenith) * 1.2);
}

TEST_CASE("perez: bad Perez input is refused with its place", "[daylight]") {
    CHECK_THAT(refused(R"({"sky": {"type": "perez", "direct_normal_irradiance": 500, "diffuse_horizontal_irradiance": 100}})"),
               Catch::Contains("/daylight/sun") && Catch::Contains("Perez"));
    CHECK_THAT(refused(R"({"sky": {"type": "perez", "diffuse_horizontal_irradiance": 100, "diffuse_horizontal_illuminance": 9000},
                          "sun": {"altitude": 30, "azimuth": 180}})"),
               Catch::Contains("/daylight/sky") && Catch::Contains("either"));
    CHECK_THAT(refused(R"({"sky": {"type": "perez", "direct_normal_irradiance": 500, "diffuse_horizontal_irradiance": 100},
                          "sun": {"altitude": 30, "azimuth": 180, "direct_normal_illuminance": 50000}})"),
               Catch::Contains("/daylight/sun") && Catch::Contains("leave out"));
    CHECK_THAT(refused(R"({"sky": {"type": "perez", "direct_normal_irradiance": 5000, "diffuse_horizontal_irradiance": 100},
                          "sun": {"altitude": 30, "azimuth": 180}})"),
               Catch::Contains("/daylight/sky/direct_normal_irradiance"));
    CHECK_THAT(refused(R"({"sky": {"type": "perez", "direct_normal_irradiance": 500, "diffuse_horizontal_irradiance": 100,
                          "dew_point": 90}, "sun": {"altitude": 30, "azimuth": 180}})"),
               Catch::Contains("/daylight/sky/dew_point"));
    CHECK(refused(R"({"sky": {"type": "perez", "direct_normal_irradiance": 500, "diffuse_horizontal_irradiance": 100},
                      "sun": {"altitude": 30, "azimuth": 180}})")
              .empty());
}
