// Saved solutions (issue 16): the round trip is exact; every truncation and every flipped
// byte is refused with an InputError, never a crash or a wrong solution.
#include <core/input_error.h>
#include <radiosity/solution_file.h>

#include "test_support.h"

#include <catch2/catch.hpp>

using namespace rayrad;
using namespace rayrad::radiosity;

namespace {

RadiositySolution smallSolution(size_t patches, size_t vertices) {
    RadiositySolution s;
    for (size_t i = 0; i < patches; ++i) {
        s.directMean.push_back(Rgb(1.0 + i, 2.0, 3.0));
        s.indirect.push_back(Rgb(0.5 * i, 0.25, 0.125));
        s.unshot.push_back(Rgb(-1e-3 * i));
        for (int k = 0; k < 3; ++k) s.directCorner.push_back(RgbF(float(i + k)));
    }
    for (size_t v = 0; v < vertices; ++v) s.vertexIndirect.push_back(Rgb(v * 0.1));
    s.shots = 42;
    s.initialUnshotFlux = 100;
    s.remainingUnshotFlux = 0.09;
    s.converged = true;
    s.backFlux = {0.0, 1.5};
    return s;
}

}  // namespace

TEST_CASE("a saved solution reads back exactly, and any damage is refused", "[solution]") {
    const SolutionFingerprint f{1, 2, 3, 4};
    const RadiositySolution s = smallSolution(5, 7);
    const std::string bytes = encodeSolution(s, f, 7);
    const RadiositySolution back = decodeSolution(bytes, "s.rrs", f, 5, 7);
    CHECK(back.directMean == s.directMean);
    CHECK(back.directCorner == s.directCorner);
    CHECK(back.indirect == s.indirect);
    CHECK(back.unshot == s.unshot);
    CHECK(back.vertexIndirect == s.vertexIndirect);
    CHECK(back.shots == 42);
    CHECK(back.converged);
    CHECK(back.backFlux == s.backFlux);
    // Another scene: each part of the fingerprint is named.
    CHECK_THROWS_WITH(decodeSolution(bytes, "s.rrs", {9, 2, 3, 4}, 5, 7), Catch::Contains("the geometry"));
    CHECK_THROWS_WITH(decodeSolution(bytes, "s.rrs", {1, 9, 3, 4}, 5, 7), Catch::Contains("the materials differ"));
    CHECK_THROWS_WITH(decodeSolution(bytes, "s.rrs", {1, 2, 9, 4}, 5, 7), Catch::Contains("the lights differ"));
    CHECK_THROWS_WITH(decodeSolution(bytes, "s.rrs", {1, 2, 3, 9}, 5, 7), Catch::Contains("settings differ"));
    // Every truncation and every flipped byte.
    int refused = 0;
    for (size_t n = 0; n < bytes.size(); ++n) {
        try {
            decodeSolution(bytes.substr(0, n), "s.rrs", f, 5, 7);
        } catch (const InputError&) {
            ++refused;
        }
    }
    CHECK(refused == static_cast<int>(bytes.size()));
    refused = 0;
    for (size_t i = 0; i < bytes.size(); ++i) {
        std::string damaged = bytes;
        damaged[i] = static_cast<char>(damaged[i] ^ 0x10);
        try {
            decodeSolution(damaged, "s.rrs", f, 5, 7);
        } catch (const InputError&) {
            ++refused;
        }
    }
    CHECK(refused == static_cast<int>(bytes.size()));
}
