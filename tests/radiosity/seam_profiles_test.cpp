// Seam profiles : the display values graded toward concave seams.
#include <radiosity/solution/seam_profiles.h>
#include <radiosity/solution/solution.h>
#include "solved_scene.h"

#include "test_support.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <map>

using namespace rayrad;
using namespace rayrad::radiosity;

namespace {

/// The Cornell box with sensors in two rows running away from the seam where the ceiling
/// meets the back wall (bench/seam_profile.py's rows at x = 0.10 and 0.45 m), 1 to 25 mm:
/// the band of triangles along the seam (the scene's max_edge is 0.05 m).
std::string cornellSeamRows() {
    std::ifstream in(test::sourcePath("scenes/cornell/cornell.json"));
    nlohmann::json scene = nlohmann::json::parse(in);
    const double ceilingY = 0.5488, backZ = 0.5592;
    scene["sensors"] = nlohmann::json::array();
    scene.erase("sensor_grids");
    for (double x : {0.10, 0.45})
        for (double mm : {1.0, 4.0, 8.0, 15.0, 25.0}) {
            scene["sensors"].push_back({{"name", fmt::format("ceiling {} {}", x, mm)},
                                        {"position", {x, ceilingY, backZ - mm / 1000}},
                                        {"normal", {0, -1, 0}}});
            scene["sensors"].push_back({{"name", fmt::format("wall {} {}", x, mm)},
                                        {"position", {x, ceilingY - mm / 1000, backZ}},
                                        {"normal", {0, 0, -1}}});
        }
    return test::writeTempScene("cornell_seam_rows", scene.dump());
}

/// The largest |mesh − gather| / gather over the run's sensors.
double worstMeshError(const test::SolvedScene& run) {
    double worst = 0;
    std::string where;
    for (const auto& s : run.sensors) {
        REQUIRE(s.value.indirectVertex);
        const double gather = luminance(s.value.indirect), mesh = luminance(*s.value.indirectVertex);
        if (std::abs(mesh / gather - 1) > worst)
            worst = std::abs(mesh / gather - 1),
            where = fmt::format("{}: gather {:.4g}, mesh {:.4g} lx", s.sensor.name, gather, mesh);
    }
    UNSCOPED_INFO("worst " << where);
    return worst;
}

}  // namespace

TEST_CASE("seam profiles: beside the Cornell box's ceiling seam the mesh reads the gathered light", "[solver]") {
    // Linear elements read up to 11 % low over the band of triangles along the seam (the
    // light rises like d ln(1/d) away from it); the profiles bring the band within 2.5 %
    // (farther out, at the next row of vertices, the reconstruction's own −3 % remains).
    const std::string scene = cornellSeamRows();
    auto without = test::solve(scene, {{"radiosity.seam_profile_nodes", "0"}});
    auto with = test::solve(scene);
    CHECK(without.lighting.solution.seamProfiles.empty());
    CHECK(with.lighting.solution.seamProfiles.edgeCount() > 100);
    CHECK(worstMeshError(without) > 0.08);
    CHECK(worstMeshError(with) < 0.025);
}

TEST_CASE("seam profiles: the display is continuous across every edge and follows each profile", "[solver]") {
    // On an edge both triangles must show the same correction (else the mesh's lines show),
    // at a seam vertex none (its gathered value stands), and at a profiled edge's nodes
    // the profile's own values.
    auto run = test::solve(test::sourcePath("scenes/cornell/cornell.json"));
    const auto& mesh = run.mesh;
    const SeamProfiles& profiles = run.lighting.solution.seamProfiles;
    REQUIRE(!profiles.empty());
    // Barycentrics (u, v) of a patch's point λ0 c0 + λ1 c1 + λ2 c2.
    auto at = [&](size_t patch, int a, int b, double t) {  // the point (1 − t) corner a + t corner b
        std::array<double, 3> l{0, 0, 0};
        l[a] += 1 - t, l[b] += t;
        return profiles.deltaAt(patch, l[1], l[2]);
    };
    // Every edge's triangles, by its vertices.
    std::map<std::pair<uint32_t, uint32_t>, std::vector<std::pair<size_t, std::pair<int, int>>>> sides;
    for (size_t i = 0; i < mesh.patches.size(); ++i)
        for (int k = 0; k < 3; ++k) {
            const uint32_t a = mesh.patches[i].v[k], b = mesh.patches[i].v[(k + 1) % 3];
            const bool ascending = a < b;
            sides[{std::min(a, b), std::max(a, b)}].push_back(
                {i, ascending ? std::make_pair(k, (k + 1) % 3) : std::make_pair((k + 1) % 3, k)});
        }
    size_t shared = 0, nonzero = 0;
    double worst = 0;
    for (const auto& [edge, list] : sides) {
        if (list.size() != 2) continue;
        ++shared;
        for (double t : {0.0, 0.1, 0.3, 0.5, 0.77, 1.0}) {
            const Rgb one = at(list[0].first, list[0].second.first, list[0].second.second, t);
            const Rgb two = at(list[1].first, list[1].second.first, list[1].second.second, t);
            worst = std::max(worst, double(glm::length(one - two)));
            nonzero += glm::length(one) > 1e-3;
        }
    }
    CHECK(shared > 1000);
    CHECK(nonzero > 100);  // the corrections are there
    CHECK(worst < 1e-9);   // and no edge shows
    // Nodes: δ at τ_k of every profiled edge, seen from a patch holding the edge.
    const auto& seams = profiles.seamVertices();
    size_t checked = 0;
    for (const auto& e : profiles.edges()) {
        CHECK(std::binary_search(seams.begin(), seams.end(), e.from));
        CHECK(!std::binary_search(seams.begin(), seams.end(), e.to));
        for (const auto& [patch, corners] : sides[{std::min(e.from, e.to), std::max(e.from, e.to)}]) {
            const auto& v = mesh.patches[patch].v;
            const int from = v[corners.first] == e.from ? corners.first : corners.second;
            const int to = from == corners.first ? corners.second : corners.first;
            CHECK(glm::length(at(patch, from, to, 0.0)) < 1e-9);
            CHECK(glm::length(at(patch, from, to, 1.0)) < 1e-9);
            for (int k = 0; k < SeamProfiles::kNodes; ++k)
                CHECK(glm::length(at(patch, from, to, std::ldexp(1.0, -(k + 1))) - Rgb(e.delta[k])) <
                      1e-5 * (1 + glm::length(Rgb(e.delta[k]))));
            ++checked;
        }
    }
    CHECK(checked >= profiles.edgeCount());
}
