// False colour: scale levels, palette, and a picture with a legend in a real font.
#include <tonemap/false_colour.h>

#include <catch2/catch.hpp>

#include <cmath>

using namespace rayrad;

TEST_CASE("false-colour scales: linear from 0 or from below a uniform field's minimum, log in 1-2-5 steps",
          "[tonemap][falsecolour]") {
    tonemap::FalseColourOptions linear;
    CHECK(tonemap::scaleLevels(0, 730, linear) == std::vector<double>{0, 100, 200, 300, 400, 500, 600, 700, 800});
    CHECK(tonemap::scaleLevels(511, 653, linear) == std::vector<double>{500, 520, 540, 560, 580, 600, 620, 640, 660});
    tonemap::FalseColourOptions log;
    log.logScale = true;
    log.decades = 2;
    CHECK(tonemap::scaleLevels(0, 1000, log) == std::vector<double>{10, 20, 50, 100, 200, 500, 1000});
    float lo[3], hi[3];
    tonemap::paletteColour(0, lo);
    tonemap::paletteColour(1, hi);
    CHECK(lo[2] > lo[0]);  // dark blue at the bottom
    CHECK(hi[0] > hi[2]);  // dark red at the top
}

TEST_CASE("a false-colour picture: the field, isolines at the levels, a legend with text", "[tonemap][falsecolour]") {
    tonemap::ScalarField field;
    field.width = 10;
    field.height = 6;
    for (int y = 0; y < field.height; ++y)
        for (int x = 0; x < field.width; ++x) field.values.push_back(x < 2 && y < 2 ? NAN : 100.0 * x);  // a hole, a ramp
    tonemap::FalseColourOptions o;
    o.unit = "lx";
    o.title = "ramp";
    o.pixelsPerValue = 20;
    const auto p = tonemap::renderFalseColour(field, o);
    REQUIRE(p.width > 200);
    REQUIRE(p.height >= 6 * 20);
    auto pixel = [&](int x, int y, int c) { return static_cast<int>(p.rgb[(static_cast<size_t>(y) * p.width + x) * 3 + c]); };
    // Inside the hole: grey; at the ramp's high end: reddish; some dark isoline pixels in between.
    const int top = 12 + 15 * 2;  // margin + title
    CHECK(pixel(12 + 10, top + 10, 0) == pixel(12 + 10, top + 10, 2));
    CHECK(pixel(12 + 195, top + 100, 0) > pixel(12 + 195, top + 100, 2));
    int dark = 0, ink = 0;
    for (int x = 12; x < 12 + 200; ++x)
        if (pixel(x, top + 100, 0) < 40 && pixel(x, top + 100, 1) < 40) ++dark;
    // The legend's labels are drawn: dark pixels right of the colour bar.
    for (int y = 0; y < p.height; ++y)
        for (int x = 12 + 200 + 20 + 34; x < p.width; ++x)
            if (pixel(x, y, 0) < 100) ++ink;
    CHECK(dark >= 4);  // levels every 200 lx up to 900: four isolines cross the ramp
    CHECK(ink > 100);
}
