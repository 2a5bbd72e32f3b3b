// Grid statistics: Emin, Eavg, Emax, U0 = Emin/Eavg and Emin/Emax per grid.
#include <app/false_colour_output.h>
#include <app/grid_statistics.h>
#include <app/pipeline.h>

#include "test_support.h"

#include <catch2/catch.hpp>

using namespace rayrad;

TEST_CASE("grid statistics: minimum, mean, maximum and uniformities of each grid's total illuminance", "[app][grids]") {
    std::vector<app::SensorResult> results;
    auto add = [&](const std::string& grid, double direct, double indirect) {
        app::SensorResult r;
        r.sensor.name = grid + "[" + std::to_string(results.size()) + "]";
        r.sensor.grid = grid;
        r.value.direct = Rgb(direct);
        r.value.indirect = Rgb(indirect);
        results.push_back(r);
    };
    add("desk", 300, 100);  // 400
    add("", 1000, 0);       // a single sensor: in no grid
    add("desk", 150, 50);   // 200
    add("floor", 80, 20);   // 100
    add("desk", 500, 100);  // 600
    const auto grids = app::gridStatistics(results);
    REQUIRE(grids.size() == 2);
    CHECK(grids[0].grid == "desk");
    CHECK(grids[0].points == 3);
    CHECK(grids[0].minimum == Approx(200));
    CHECK(grids[0].mean == Approx(400));
    CHECK(grids[0].maximum == Approx(600));
    CHECK(grids[0].u0() == Approx(0.5));
    CHECK(grids[0].minToMax() == Approx(200.0 / 600));
    CHECK(grids[1].grid == "floor");
    CHECK(grids[1].u0() == Approx(1));
    CHECK(app::gridCsv(grids) ==
          "grid,points,emin_lx,eavg_lx,emax_lx,u0,emin_emax,excluded_points,emedian_lx,df_min_pct,df_mean_pct,"
          "df_median_pct\n"
          "desk,3,200,400,600,0.500000,0.333333,0,400,,,\nfloor,1,100,100,100,1.000000,1.000000,0,100,,,\n");
    CHECK(app::gridSummaryPath("out/room.csv") == "out/room.grids.csv");
}

TEST_CASE("grid statistics: daylight factors, their median and EN 17037's method 1", "[app]") {
    std::vector<app::SensorResult> results;
    const double factors[] = {0.5, 1.0, 2.0, 3.0};  // %
    for (int i = 0; i < 4; ++i) {
        app::SensorResult r;
        r.sensor.name = "p" + std::to_string(i);
        r.sensor.grid = "plane";
        r.value.direct = Rgb(100 * factors[i]);  // lx under a 10 000 lx sky
        r.daylightFactor = factors[i];
        results.push_back(r);
    }
    // E_v,d,med 15 000 lx: D_T = 2 %, D_TM = 0.667 %: 2 of 4 points reach D_T, 3 of 4 D_TM.
    const auto grids = app::gridStatistics(results, 15000.0);
    REQUIRE(grids.size() == 1);
    CHECK(*grids[0].dfMinimum == Approx(0.5));
    CHECK(*grids[0].dfMean == Approx(1.625));
    CHECK(*grids[0].dfMedian == Approx(1.5));
    CHECK(grids[0].median == Approx(150));
    CHECK(*grids[0].dfTarget == Approx(2.0));
    CHECK(*grids[0].shareAboveTarget == Approx(0.5));
    CHECK(*grids[0].shareAboveTargetMinimum == Approx(0.75));
    CHECK_FALSE(grids[0].meetsEn17037Minimum());  // 95 % must reach D_TM
    CHECK_THAT(app::gridTable(grids), Catch::Contains("the minimum level is not met"));
    // Its plan shows the daylight factor, the shares on a second line.
    CHECK(app::gridPlanTitle(grids[0]) ==
          "plane: daylight factor min 0.50, mean 1.62, median 1.50 %, U0 0.31\n"
          "EN 17037 method 1: DF >= 2.0 % on 50 % (50 % asked), >= 0.7 % on 75 % (95 % asked): not met");
}

TEST_CASE("grid statistics leave out points inside solids and count them", "[app][grids]") {
    std::vector<app::SensorResult> results;
    for (double e : {400.0, 0.0, 200.0}) {
        app::SensorResult r;
        r.sensor.grid = "floor";
        r.value.direct = Rgb(e);
        if (e == 0) r.excluded = "inside a solid";
        results.push_back(r);
    }
    const auto grids = app::gridStatistics(results);
    REQUIRE(grids.size() == 1);
    CHECK(grids[0].points == 2);
    CHECK(grids[0].excluded == 1);
    CHECK(grids[0].minimum == Approx(200));
    CHECK(grids[0].u0() == Approx(200.0 / 300));
    CHECK(app::sensorCsv(results).find(",excluded\n") != std::string::npos);
    CHECK(app::sensorCsv(results).find(",inside a solid\n") != std::string::npos);
}

TEST_CASE("the Cornell box's floor grid: the two points inside the blocks are left out", "[app][grids]") {
    app::PipelineOptions o;
    o.quiet = true;
    o.overrides = {{"radiosity.max_edge", "0.1"}};
    const auto run = app::runPipeline(test::sourcePath("scenes/cornell/cornell.json"), o);
    const auto grids = app::gridStatistics(run.sensors);
    REQUIRE(grids.size() == 1);
    CHECK(grids[0].points == 14);
    CHECK(grids[0].excluded == 2);
    CHECK(grids[0].minimum > 0);
}
