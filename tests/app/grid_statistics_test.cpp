// Grid statistics (issue 14): Emin, Eavg, Emax, U0 = Emin/Eavg and Emin/Emax per grid.
#include <app/grid_statistics.h>

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
          "grid,points,emin_lx,eavg_lx,emax_lx,u0,emin_emax\ndesk,3,200,400,600,0.500000,0.333333\nfloor,1,100,100,100,1.000000,1.000000\n");
    CHECK(app::gridSummaryPath("out/room.csv") == "out/room.grids.csv");
}
