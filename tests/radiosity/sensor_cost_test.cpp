// The sensor stage's warning of its own cost, from what the first sensors took.
#include <radiosity/gather/sensors.h>

#include <catch2/catch.hpp>

using namespace rayrad;

TEST_CASE("sensors: a stage that will take long says so from its measured cost", "[sensors]") {
    // Six seconds for the first 1 of 42 (a furnished house): 4.2 CPU-minutes, not worth a word.
    CHECK_FALSE(radiosity::slowSensorsWarning(1, 42, 6.0));
    // The same cost over a 1 000-point work plane: 100 minutes, said with the figures.
    const auto w = radiosity::slowSensorsWarning(1, 1000, 6.0);
    REQUIRE(w);
    CHECK(w->find("the first 1 of 1000 sensors took 6 CPU-s each") != std::string::npos);
    CHECK(w->find("about 100 CPU-minutes") != std::string::npos);
    // Not before the probe time has gone, nor at the end, nor before any sensor is done.
    CHECK_FALSE(radiosity::slowSensorsWarning(1, 1000, 0.5 * radiosity::kSensorProbeSeconds));
    CHECK_FALSE(radiosity::slowSensorsWarning(1000, 1000, 6000.0));
    CHECK_FALSE(radiosity::slowSensorsWarning(0, 1000, 60.0));
    // A million fast sensors: 1 ms each is 17 minutes.
    CHECK(radiosity::slowSensorsWarning(5000, 1'000'000, 5.0));
}
