// Facing bounds: a member-tree leaf the gather skips is one whose patches would all have
// given the point a form factor of exactly 0.
#include <radiosity/clusters.h>
#include <radiosity/facing_bounds.h>
#include <radiosity/member_tree.h>
#include <radiosity/mesher.h>
#include <radiosity/patch_transfer.h>
#include <scene/scene_parser.h>

#include "test_support.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace rayrad;
using namespace rayrad::radiosity;

TEST_CASE("facing bounds: a skipped leaf's patches all have a zero form factor, and leaves are skipped", "[gather]") {
    // The Cornell box: walls and two blocks, faces in six directions.
    auto s = scene::buildScene(scene::loadScene(test::sourcePath("scenes/cornell/cornell.json"),
                                                {{"radiosity.max_edge", "0.1"}}));
    const PatchMesh mesh = premesh(s, s.meshing);
    const Clustering clustering = buildClusters(s, mesh, s.clusters);
    std::vector<MemberTree> trees;
    std::vector<std::vector<NormalCone>> cones;
    for (const Cluster& C : clustering.clusters) {
        trees.push_back(memberTree(mesh, C, 8));
        cones.push_back(normalCones(mesh, C, trees.back()));
    }
    // Points on the surfaces (a patch's centroid, its normal, as the gathers take them)
    // and inside the box with normals in every direction.
    std::vector<std::pair<Vec3, Vec3>> points;
    for (size_t i = 0; i < mesh.patches.size(); i += 37) points.push_back({mesh.patches[i].centroid, mesh.patches[i].normal});
    for (int k = 0; k < 60; ++k) {
        const double a = 0.7 * k, b = 1.3 * k;
        const Vec3 n(std::cos(a) * std::sin(b), std::cos(b), std::sin(a) * std::sin(b));
        points.push_back({Vec3(0.05 + 0.45 * std::fmod(0.37 * k, 1.0), 0.05 + 0.45 * std::fmod(0.61 * k, 1.0),
                               0.05 + 0.45 * std::fmod(0.83 * k, 1.0)), glm::normalize(n)});
    }
    size_t leaves = 0, skipped = 0, zeroNotSkipped = 0;
    for (const auto& [x, n] : points) {
        for (size_t c = 0; c < trees.size(); ++c) {
            const Cluster& C = clustering.clusters[c];
            for (size_t i = 0; i < trees[c].nodes.size(); ++i) {
                const MemberNode& node = trees[c].nodes[i];
                if (!node.leaf()) continue;
                ++leaves;
                const bool skip = bringsNothing(node, cones[c][i], x, n);
                skipped += skip;
                bool allZero = true;
                for (uint32_t k = node.begin; k < node.end; ++k) {
                    const Patch& p = mesh.patches[C.patches[trees[c].order[k]]];
                    // Lambert's formula (analytic within 1e9 diameters) and the point
                    // approximation (within none): both exactly 0 for a skipped leaf.
                    const double lambert = patchFormFactor(mesh, p, x, n, 1e9), point = patchFormFactor(mesh, p, x, n, 0);
                    if (skip) {
                        REQUIRE(lambert == 0.0);
                        REQUIRE(point == 0.0);
                    }
                    allZero &= lambert == 0.0 && point == 0.0;
                }
                zeroNotSkipped += !skip && allZero;
            }
        }
    }
    INFO("leaves " << leaves << ", skipped " << skipped << ", all-zero leaves not skipped " << zeroNotSkipped);
    // Most leaves a point cannot see are found: those behind it, and those facing away.
    REQUIRE(skipped > 0.5 * (skipped + zeroNotSkipped));
}
