// Saved solutions: the round trip is exact; every truncation and every flipped
// byte is refused with an InputError, never a crash or a wrong solution.
#include <core/input_error.h>
#include <radiosity/solution/solution_file.h>

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
        for (int k = 0; k < 3; ++k) s.directCorner.push_back(RgbF(float(i + k)));
    }
    for (size_t v = 0; v < vertices; ++v) s.vertexIndirect.push_back(Rgb(v * 0.1));
    s.shots = 42;
    s.emittedFlux = 350;
    s.initialUnshotFlux = 100;
    s.remainingUnshotFlux = 0.09;
    s.unshotNetFlux = -0.07;
    s.converged = true;
    s.backFlux = {0.0, 1.5};
    // Seam profiles from vertices 0 and 1 (vertices ≥ 4 needed).
    SeamProfiles::Edge a, b;
    a.from = 0, a.to = 2, b.from = 1, b.to = 3;
    for (int k = 0; k < SeamProfiles::kNodes; ++k) a.delta[k] = RgbF(float(k + 1)), b.delta[k] = RgbF(-0.5f * float(k));
    s.seamProfiles = SeamProfiles({0, 1}, {a, b});
    return s;
}

SolutionFingerprint fingerprint(uint64_t geometry, uint64_t materials, uint64_t lights, uint64_t settings,
                                uint64_t shapes = 5) {
    SolutionFingerprint f;
    f.geometry = geometry, f.materials = materials, f.lights = lights, f.settings = settings, f.lightShapes = shapes;
    return f;
}

}  // namespace

TEST_CASE("a saved solution reads back exactly, and any damage is refused", "[solution]") {
    const SolutionFingerprint f = fingerprint(1, 2, 3, 4);
    const RadiositySolution s = smallSolution(5, 7);
    const std::string bytes = encodeSolution(s, f, 7);
    const RadiositySolution back = decodeSolution(bytes, "s.rrs", f, 5, 7);
    CHECK(back.directMean == s.directMean);
    CHECK(back.directCorner == s.directCorner);
    CHECK(back.indirect == s.indirect);
    CHECK(back.unshotNetFlux == s.unshotNetFlux);
    CHECK(back.vertexIndirect == s.vertexIndirect);
    CHECK(back.shots == 42);
    CHECK(back.emittedFlux == 350);
    CHECK(back.initialUnshotFlux == 100);
    CHECK(back.converged);
    CHECK(back.backFlux == s.backFlux);
    CHECK(back.seamProfiles.seamVertices() == s.seamProfiles.seamVertices());
    REQUIRE(back.seamProfiles.edgeCount() == 2);
    for (size_t e = 0; e < 2; ++e) {
        CHECK(back.seamProfiles.edges()[e].from == s.seamProfiles.edges()[e].from);
        CHECK(back.seamProfiles.edges()[e].to == s.seamProfiles.edges()[e].to);
        CHECK(back.seamProfiles.edges()[e].delta == s.seamProfiles.edges()[e].delta);
    }
    // Another scene: each part of the fingerprint is named.
    CHECK_THROWS_WITH(decodeSolution(bytes, "s.rrs", fingerprint(9, 2, 3, 4), 5, 7), Catch::Contains("the geometry"));
    CHECK_THROWS_WITH(decodeSolution(bytes, "s.rrs", fingerprint(1, 9, 3, 4), 5, 7),
                      Catch::Contains("the materials differ"));
    CHECK_THROWS_WITH(decodeSolution(bytes, "s.rrs", fingerprint(1, 2, 3, 4, 9), 5, 7),
                      Catch::Contains("the lights differ"));
    // Only dimmed (the shapes agree), but the file has no light groups' parts.
    CHECK_THROWS_WITH(decodeSolution(bytes, "s.rrs", fingerprint(1, 2, 9, 4), 5, 7),
                      Catch::Contains("only dimming whole light groups can be applied"));
    CHECK_THROWS_WITH(decodeSolution(bytes, "s.rrs", fingerprint(1, 2, 3, 9), 5, 7),
                      Catch::Contains("settings differ"));
    // A file of another format version (the uint32 after the 10-byte magic "RAYRADSOL\0")
    // says so and what to do.
    std::string older = bytes;
    older[10] = static_cast<char>(older[10] - 1);
    CHECK_THROWS_WITH(decodeSolution(older, "s.rrs", f, 5, 7), Catch::Contains("solve the scene again"));
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

TEST_CASE("a saved solution with light groups follows the groups' dimming", "[solution]") {
    SolutionFingerprint saved = fingerprint(1, 2, 3, 4);
    saved.groupStrengths = {{"", 2.0}, {"desk", 3.0}};
    const RadiositySolution full = smallSolution(5, 7);
    std::vector<GroupSolution> parts = {{"", smallSolution(5, 7)}, {"desk", smallSolution(5, 7)}};
    for (auto& v : parts[1].solution.indirect) v *= 10.0;
    const std::string bytes = encodeSolution(full, saved, 7, parts);
    // The same lights: the full solve itself.
    CHECK(decodeSolution(bytes, "s.rrs", saved, 5, 7).indirect == full.indirect);
    // The ungrouped lights at half their strength, the desk group as it was.
    SolutionFingerprint dimmed = fingerprint(1, 2, 33, 4);
    dimmed.groupStrengths = {{"", 1.0}, {"desk", 3.0}};
    const RadiositySolution mixed = decodeSolution(bytes, "s.rrs", dimmed, 5, 7);
    for (size_t i = 0; i < mixed.indirect.size(); ++i)
        CHECK(mixed.indirect[i].x == Approx(0.5 * parts[0].solution.indirect[i].x + parts[1].solution.indirect[i].x));
    CHECK(mixed.directMean[2].y == Approx(1.5 * parts[0].solution.directMean[2].y));
    // The seam profiles add alike, edge by edge: (0.5 + 1) times each part's.
    REQUIRE(mixed.seamProfiles.edgeCount() == 2);
    CHECK(mixed.seamProfiles.edges()[0].delta[2].x == Approx(1.5 * 3.0));
    CHECK(mixed.seamProfiles.edges()[1].delta[4].z == Approx(1.5 * -2.0));
    // Another group's name: refused.
    dimmed.groupStrengths[1].first = "window";
    CHECK_THROWS_WITH(decodeSolution(bytes, "s.rrs", dimmed, 5, 7),
                      Catch::Contains("light groups are not the scene's"));
}
