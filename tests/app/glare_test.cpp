// Glare: the formulas on hand-computed cases, the CIE 190 UGR table against the tables of
// DIALux, Relux and CIE 190 itself, and UGR at an observer against the table in the
// standard room.
#include <app/glare/fisheye_glare.h>
#include <app/glare/glare_formulas.h>
#include <app/glare/observer_glare.h>
#include <app/glare/ugr_table.h>
#include <app/validate_glare.h>
#include <core/input_error.h>
#include <scene/photometry.h>

#include "pipeline_test_util.h"
#include "test_support.h"

#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <cmath>

using namespace rayrad;

namespace {

/// The largest |ours − reference| over the entries both give (at least 180 of them).
double largestDifference(const app::UgrTable& ours, const std::string& reference) {
    int compared = 0;
    const double worst =
        app::largestUgrDifference(ours, app::readUgrReference(test::sourcePath("tests/data/ugr/" + reference)), &compared);
    CHECK(compared >= 180);
    return worst;
}

scene::Photometry luminaireFile(const std::string& name) {
    return scene::readPhotometry(test::sourcePath("tests/data/luminaires/" + name));
}

}  // namespace

TEST_CASE("glare: Guth's position index at points of CIE 117's table", "[glare]") {
    CHECK(app::positionIndex(Vec3(0, 0, 1)) == Approx(1.0));
    // Straight above the line of sight at 45° (H/R = 1, T/R = 0): the table gives 7.00.
    const double s = std::sqrt(0.5);
    CHECK(app::positionIndex(Vec3(0, s, s)) == Approx(7.00).epsilon(0.02));
    // Level, 45° to the side (H/R = 0, T/R = 1): the table gives 2.11.
    CHECK(app::positionIndex(Vec3(s, 0, s)) == Approx(2.11).epsilon(0.05));
    // Left and right alike; behind the eye, outside any field.
    CHECK(app::positionIndex(Vec3(-s, 0, s)) == Approx(app::positionIndex(Vec3(s, 0, s))));
    CHECK(std::isinf(app::positionIndex(Vec3(0, 1, -0.1))));
    // Below the line of sight a source weighs as one 1.15 times farther to the side.
    CHECK(app::positionIndex(Vec3(0, -0.3, 1)) > app::positionIndex(Vec3(0.3, 0, 1)));
}

TEST_CASE("glare: UGR and DGP of one source, computed by hand", "[glare]") {
    app::GlareSource src;
    src.luminance = 10000;
    src.solidAngle = 0.01;
    src.positionIndex = 2;
    // 8 log10(0.25 / 20 · 10⁸ · 0.01 / 4) = 8 log10(3125)
    REQUIRE(app::unifiedGlareRating(20, {src}));
    CHECK(*app::unifiedGlareRating(20, {src}) == Approx(27.9588).epsilon(1e-5));
    CHECK_FALSE(app::unifiedGlareRating(20, {}));
    src.positionIndex = 17;  // beyond the table's field
    CHECK_FALSE(app::unifiedGlareRating(20, {src}));

    app::GlareSource sun;
    sun.luminance = 5000;
    sun.solidAngle = 0.005;
    sun.positionIndex = 1.5;
    // 5.87e-5 · 2000 + 9.18e-2 log10(1 + 5000² · 0.005 / (2000^1.87 · 1.5²)) + 0.16
    CHECK(app::daylightGlareProbability(2000, {sun}) == Approx(0.278860).epsilon(1e-5));
    // Below 1 000 lx, times the low-light correction e^(0.024·500 − 4) / (1 + e^(...)).
    CHECK(app::daylightGlareProbability(500, {sun}) == Approx(0.205406).epsilon(1e-5));
    CHECK(app::dgpClass(0.30) == "imperceptible");
    CHECK(app::dgpClass(0.36) == "perceptible");
    CHECK(app::dgpClass(0.42) == "disturbing");
    CHECK(app::dgpClass(0.45) == "intolerable");
}

TEST_CASE("glare: the walls' transfer factors reproduce CIE 190's Table 5", "[glare]") {
    struct Case {
        double x, y;
        app::RoomReflectances rho;
        double fw, ww, cw;  // CIE 190 Table 5: FT.FW, FT.WW − 1, FT.CW
    };
    const Case cases[] = {{4, 4, {0.7, 0.5, 0.2}, 0.142, 0.265, 0.389},
                          {2, 2, {0.3, 0.3, 0.2}, 0.157, 0.181, 0.227},
                          {12, 8, {0.7, 0.5, 0.2}, 0.071, 0.133, 0.183},
                          {4, 8, {0.5, 0.3, 0.2}, 0.093, 0.104, 0.196}};
    for (const auto& c : cases) {
        const auto ft = app::wallTransferFactors(c.x, c.y, 1.0, c.rho);
        INFO(fmt::format("room {}H x {}H", c.x, c.y));
        CHECK(ft.fromFloor == Approx(c.fw).margin(6e-4));
        CHECK(ft.fromWalls == Approx(c.ww).margin(6e-4));
        CHECK(ft.fromCeiling == Approx(c.cw).margin(6e-4));
    }
}

TEST_CASE("glare: UGR tables against DIALux, Relux and CIE 190's own table", "[glare]") {
    // Each within the spread the programs show among themselves (DIALux and Relux differ
    // by up to 0.8 on these files).
    for (const char* n : {"01", "05", "11"}) {
        const auto p = luminaireFile(fmt::format("eulumdatugr_sample_{}.ldt", n));
        const app::UgrTable table = app::ugrTable(p, 0.25);
        INFO("sample " << n);
        CHECK(largestDifference(table, fmt::format("sample_{}_Relux.csv", n)) <= 0.5);
        CHECK(largestDifference(table, fmt::format("sample_{}_Dialux.csv", n)) <= 0.7);
    }
    // CIE 190's standard-condition table for its example luminaire: spacing 1 H.
    const app::UgrTable cie = app::ugrTable(luminaireFile("eulumdatugr_sample_11.ldt"), 1.0);
    CHECK(largestDifference(cie, "sample_11_cie190.csv") <= 0.3);
}

TEST_CASE("glare: a rotationally symmetric luminaire reads the same crosswise and endwise", "[glare]") {
    const app::UgrTable t = app::ugrTable(luminaireFile("eulumdatugr_sample_05.ldt"), 0.25);
    for (const auto& row : t.values)
        for (int k = 0; k < 5; ++k) {
            REQUIRE(row[k]);
            CHECK(*row[k] == Approx(*row[k + 5]).margin(1e-9));
        }
}

TEST_CASE("glare: a luminaire file without a luminous area has no UGR table", "[glare]") {
    scene::Photometry p;
    p.file = "flat.ies";
    p.vertical = {0, 90, 180};
    p.horizontal = {0};
    p.candela = {{100, 100, 0}};
    CHECK_THROWS_AS(app::ugrTable(p), InputError);
    CHECK_THROWS_WITH(app::ugrTable(p), Catch::Contains("flat.ies") && Catch::Contains("no luminous area"));
}

TEST_CASE("glare: UGR at an observer against the table in CIE 190's standard room", "[glare]") {
    const std::string ldt = test::sourcePath("tests/data/luminaires/eulumdatugr_sample_11.ldt");
    const auto run = app::runPipeline(test::writeTempScene("ugr_standard_room", app::ugrStandardRoomJson(ldt, false)),
                                      test::quiet());
    REQUIRE(run.glare.size() == 1);
    const app::ObserverGlare& g = run.glare[0];
    REQUIRE(g.ugr);
    const auto table = app::ugrTableEntry(luminaireFile("eulumdatugr_sample_11.ldt"), {4, 4}, {0.7, 0.5, 0.2}, false,
                                          1.0);
    REQUIRE(table.ugr);
    INFO(fmt::format("observer UGR {:.2f} (L_b {:.2f} cd/m²), table {:.2f} (L_b {:.2f} cd/m²)", *g.ugr,
                     g.backgroundLuminance, *table.ugr, table.backgroundLuminance));
    CHECK(std::abs(*g.ugr - *table.ugr) <= 1.0);
    CHECK(g.passes());  // within the office's 19

    SECTION("a luminaire hidden behind a wall adds nothing") {
        const auto hidden = app::runPipeline(
            test::writeTempScene("ugr_standard_room_partition", app::ugrStandardRoomJson(ldt, true)), test::quiet());
        REQUIRE(hidden.glare.size() == 1);
        const auto& h = hidden.glare[0];
        CHECK(h.sources.size() < g.sources.size());
        CHECK_FALSE(h.sources.empty());
        for (const auto& s : h.sources) {
            const int index = std::stoi(s.name.substr(s.name.rfind('/') + 1));
            INFO(s.name);
            CHECK(hidden.scene.lights[static_cast<size_t>(index)].position.x < 0);  // only the left half is seen
        }
    }
}

TEST_CASE("glare: the fisheye's pixels cover the hemisphere", "[glare]") {
    double omega = 0;
    for (int y = 0; y < 300; ++y)
        for (int x = 0; x < 300; ++x)
            if (auto p = app::fisheyePixel(300, 300, x, y)) omega += p->solidAngle;
    CHECK(omega == Approx(2 * kPi).epsilon(0.005));
}

TEST_CASE("glare: DGP and UGR of a synthetic fisheye with one known source", "[glare]") {
    // A uniform background and a round source of 5° radius, 20° above and 10° right of the
    // line of sight, against the exact cone (app::SyntheticFisheye gives both).
    const app::SyntheticFisheye f;
    const app::FisheyeGlare& g = f.found;
    REQUIRE(g.sources.size() == 1);
    const app::GlareSource& s = g.sources[0];
    INFO("source solid angle " << s.solidAngle << " sr, the cone's " << f.omega << " sr");
    CHECK(s.solidAngle == Approx(f.omega).epsilon(0.01));
    CHECK(s.luminance == Approx(app::SyntheticFisheye::luminance).epsilon(1e-9));
    CHECK(glm::dot(s.direction, f.centre) == Approx(1).margin(1e-4));
    CHECK(g.verticalIlluminance == Approx(f.ev).epsilon(0.003));
    CHECK(g.dgp == Approx(f.dgp).margin(0.002));
    REQUIRE(g.ugr);
    CHECK(*g.ugr == Approx(f.ugr).margin(0.15));
}

TEST_CASE("glare: an image that is no fisheye is refused", "[glare]") {
    HdrImage image(64, 48);
    for (auto& p : image.pixels) p = Rgb(50.0);
    CHECK_THROWS_WITH(app::analyseFisheye(image, {}, "view.exr"),
                      Catch::Contains("view.exr") && Catch::Contains("fisheye"));
    HdrImage black(64, 64);
    CHECK_THROWS_WITH(app::analyseFisheye(black, {}, "black.exr"), Catch::Contains("black"));
}
