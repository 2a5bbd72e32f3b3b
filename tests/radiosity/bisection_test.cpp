// Premeshing per element (longest-edge bisection): small triangles stay whole, large ones
// are split to size, area is kept and the result has no T-junctions.
#include <radiosity/mesh/bisection.h>

#include "test_support.h"

#include <map>
#include <utility>

using namespace rayrad;
using Triangles = std::vector<std::array<uint32_t, 3>>;

namespace {

double area(const std::vector<Vec3>& p, const std::array<uint32_t, 3>& t) {
    return 0.5 * glm::length(glm::cross(p[t[1]] - p[t[0]], p[t[2]] - p[t[0]]));
}

/// No vertex of the mesh lies strictly inside an edge of another triangle (a T-junction),
/// and every edge is used by at most two triangles.
void requireConforming(const std::vector<Vec3>& p, const Triangles& tris) {
    std::map<std::pair<uint32_t, uint32_t>, int> uses;
    std::vector<bool> used(p.size(), false);
    for (const auto& t : tris)
        for (int k = 0; k < 3; ++k) {
            uint32_t a = t[k], b = t[(k + 1) % 3];
            ++uses[{std::min(a, b), std::max(a, b)}];
            used[a] = true;
        }
    size_t shared = 0, junctions = 0;
    for (const auto& [edge, n] : uses) {
        if (n > 2) ++shared;
        const Vec3 &a = p[edge.first], &b = p[edge.second];
        for (size_t v = 0; v < p.size(); ++v) {
            if (!used[v] || v == edge.first || v == edge.second) continue;
            double s = glm::dot(p[v] - a, b - a) / glm::dot(b - a, b - a);
            if (s > 1e-9 && s < 1 - 1e-9 && glm::length(p[v] - (a + s * (b - a))) < 1e-9) ++junctions;
        }
    }
    CHECK(shared == 0);     // edges used by more than two triangles
    CHECK(junctions == 0);  // vertices inside another triangle's edge
}

}  // namespace

TEST_CASE("bisection splits a large triangle to size and leaves small neighbours whole, with no T-junction",
          "[mesher]") {
    // A 4 m square as two triangles, and beside it a strip of 200 small triangles (5 cm)
    // sharing the square's corner (4, 0).
    std::vector<Vec3> p = {{0, 0, 0}, {4, 0, 0}, {4, 4, 0}, {0, 4, 0}};
    Triangles tris = {{0, 1, 2}, {0, 2, 3}};
    // Strip vertices (4 + 0.05 i, 0) and (4 + 0.05 i, −0.05), i = 0…100; (4, 0) is vertex 1.
    auto top = [](int i) { return i == 0 ? 1u : static_cast<uint32_t>(4 + 2 * i - 1); };
    auto bottom = [](int i) { return static_cast<uint32_t>(4 + 2 * i); };
    for (int i = 0; i <= 100; ++i) {
        if (i > 0) p.push_back({4 + 0.05 * i, 0, 0});
        p.push_back({4 + 0.05 * i, -0.05, 0});
    }
    for (int i = 0; i < 100; ++i) {
        tris.push_back({top(i), bottom(i), top(i + 1)});
        tris.push_back({top(i + 1), bottom(i), bottom(i + 1)});
    }
    double before = 0;
    for (const auto& t : tris) before += area(p, t);
    auto out = radiosity::bisectToSize(p, tris, 1.0);
    double after = 0, longest = 0;
    size_t small = 0;
    for (const auto& t : out) {
        after += area(p, t);
        for (int k = 0; k < 3; ++k) longest = std::max(longest, glm::length(p[t[(k + 1) % 3]] - p[t[k]]));
        if (area(p, t) < 0.01) ++small;
    }
    CHECK(after == Approx(before).epsilon(1e-12));
    CHECK(longest <= 1.0);
    CHECK(small == 200);            // the strip is untouched
    CHECK(out.size() <= 200 + 64);  // the square: 16 m² in triangles of at most 1 m edges
    requireConforming(p, out);
    // Winding is kept: every triangle still faces +z.
    for (const auto& t : out) REQUIRE(glm::cross(p[t[1]] - p[t[0]], p[t[2]] - p[t[0]]).z > 0);
}

TEST_CASE("bisection of a sliver next to a fine mesh adds a handful of triangles, not a factor", "[mesher]") {
    // 2 000 triangles of 5 cm and one 3 m sliver sharing an edge with the first of them:
    // the old mesh-wide split (by the longest edge) made every triangle k² = 9 triangles.
    std::vector<Vec3> p = {{0, 0, 0}, {0.05, 0, 0}, {1.5, -0.01, 0}};
    Triangles tris = {{1, 0, 2}};  // the sliver, below the strip
    // Strip vertices (0.05 i, 0) and (0.05 i, 0.05), i = 0…1000; the first two bottom
    // ones are vertices 0 and 1.
    auto bottom = [](int i) { return i <= 1 ? static_cast<uint32_t>(i) : static_cast<uint32_t>(3 + 2 * (i - 2)); };
    auto top = [](int i) { return i <= 1 ? static_cast<uint32_t>(2001 + i) : static_cast<uint32_t>(4 + 2 * (i - 2)); };
    for (int i = 2; i <= 1000; ++i) {
        p.push_back({0.05 * i, 0, 0});
        p.push_back({0.05 * i, 0.05, 0});
    }
    p.push_back({0, 0.05, 0});     // 2001
    p.push_back({0.05, 0.05, 0});  // 2002
    for (int i = 0; i < 1000; ++i) {
        tris.push_back({bottom(i), bottom(i + 1), top(i + 1)});
        tris.push_back({bottom(i), top(i + 1), top(i)});
    }
    auto out = radiosity::bisectToSize(p, tris, 1.0);
    CHECK(out.size() < tris.size() + 20);
    requireConforming(p, out);
}
