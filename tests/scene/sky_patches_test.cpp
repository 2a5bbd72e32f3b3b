// The sky's patches for daylight coefficients, and the channels that light one of them.
#include <scene/daylight/daylight.h>
#include <scene/daylight/sky_patches.h>

#include "test_support.h"

#include <cmath>
#include <random>

using namespace rayrad;

TEST_CASE("sky patches: Tregenza's 145 and Reinhart's 577 and 2305, covering the sky once", "[daylight][annual]") {
    for (const auto& [mf, count] : {std::pair{1, 145}, {2, 577}, {4, 2305}}) {
        const scene::SkyPatches patches(mf);
        REQUIRE(patches.count() == count);
        double sum = 0;
        for (int p = 0; p < count; ++p) {
            sum += patches.solidAngle(p);
            CHECK(patches.patchOf(patches.centre(p)) == p);  // each centre lies in its own patch
        }
        CHECK(sum == Approx(2 * kPi).epsilon(1e-12));
        double tents = 0;
        for (int p = 0; p < count; ++p) tents += patches.tentSolidAngle(p);
        CHECK(tents == Approx(2 * kPi).epsilon(1e-9));
    }
    // Tregenza: the lowest band's first patch is centred on north, the next lies to the east.
    const scene::SkyPatches t(1);
    CHECK(t.patchOf({0, 1, 0.05}) == 0);
    CHECK(t.patchOf({std::sin(12 * kPi / 180), std::cos(12 * kPi / 180), 0.05}) == 1);
    CHECK(t.patchOf({0, 0, 1}) == 144);
    CHECK(t.solidAngle(144) == Approx(2 * kPi * (1 - std::cos(6 * kPi / 180))));
}

TEST_CASE("sky patches: the tents interpolate a sky linear between the patches' centres", "[daylight][annual]") {
    const scene::SkyPatches t(1);
    // Between two bands' centres and, within a band, two patches' centres, the weights are
    // linear: a luminance linear in altitude and in azimuth there comes back exactly.
    const double alt0 = 18 * kPi / 180, alt1 = 30 * kPi / 180;  // the centres of bands 1 and 2
    for (double f : {0.0, 0.25, 0.5, 0.9}) {
        const double a = alt0 + f * (alt1 - alt0);
        const Vec3 w(0, std::cos(a), std::sin(a));  // due north: patch 0 of each band
        const auto weights = t.weights(w);
        double altitude = 0, sum = 0;
        for (int k = 0; k < weights.count; ++k) {
            sum += weights.weight[k];
            double a0, a1, z0, z1;
            t.bounds(weights.patch[k], a0, a1, z0, z1);
            altitude += weights.weight[k] * 0.5 * (a0 + a1);
        }
        CHECK(sum == Approx(1));
        CHECK(altitude == Approx(a));
    }
}

TEST_CASE("sky channels: the patches' channels add up to the whole sky, the ground's to the ground",
          "[daylight][annual]") {
    scene::Daylight d;
    scene::setSkyAxes(d, {0, 1, 0}, {0, 0, -1});
    const auto patches = std::make_shared<const scene::SkyPatches>(1);
    std::vector<scene::Daylight> channels;
    for (int p = -1; p < patches->count(); ++p) channels.push_back(scene::channelDaylight(d, {patches, p}));
    std::mt19937 rng(7);
    std::normal_distribution<double> g;
    for (int k = 0; k < 2000; ++k) {
        const Vec3 w = glm::normalize(Vec3(g(rng), g(rng), g(rng)));
        double sky = 0;
        for (size_t c = 1; c < channels.size(); ++c) sky += channels[c].luminance(w);
        const bool below = w.y < 0;  // up is +y
        CHECK(sky == Approx(below ? 0.0 : 1.0).margin(1e-12));
        CHECK(channels[0].luminance(w) == (below ? 1.0 : 0.0));
    }
}
