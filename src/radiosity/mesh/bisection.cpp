#include <radiosity/mesh/bisection.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace rayrad::radiosity {

namespace {

using Triangle = std::array<uint32_t, 3>;
using Edge = std::pair<uint32_t, uint32_t>;  ///< sorted vertex indices

Edge edgeKey(uint32_t a, uint32_t b) {
    return a < b ? Edge{a, b} : Edge{b, a};
}

/// Index k of the longest edge (t[k], t[k+1]); ties go to the smaller sorted key, so
/// both triangles sharing an edge rank it alike.
int longestEdge(const std::vector<Vec3>& positions, const Triangle& t) {
    int best = 0;
    double bestLength = -1;
    Edge bestKey{};
    for (int k = 0; k < 3; ++k) {
        double length = glm::length(positions[t[(k + 1) % 3]] - positions[t[k]]);
        Edge key = edgeKey(t[k], t[(k + 1) % 3]);
        if (length > bestLength || (length == bestLength && key < bestKey))
            best = k, bestLength = length, bestKey = key;
    }
    return best;
}

}  // namespace

std::vector<Triangle> bisectToSize(std::vector<Vec3>& positions, std::vector<Triangle> triangles, double maxEdge,
                                   std::vector<uint32_t>* parents) {
    if (parents) {
        parents->resize(triangles.size());
        for (size_t i = 0; i < triangles.size(); ++i) (*parents)[i] = static_cast<uint32_t>(i);
    }
    for (;;) {
        // 1. Mark the longest edge of every triangle that is too large.
        std::map<Edge, uint32_t> marked;  // edge → its midpoint (assigned in step 3)
        for (const Triangle& t : triangles) {
            int k = longestEdge(positions, t);
            if (glm::length(positions[t[(k + 1) % 3]] - positions[t[k]]) > maxEdge)
                marked.emplace(edgeKey(t[k], t[(k + 1) % 3]), 0);
        }
        if (marked.empty()) return triangles;
        // 2. Closure: a triangle with any marked edge has its longest edge marked too,
        // so it can always be split at its longest edge first.
        for (bool grew = true; grew;) {
            grew = false;
            for (const Triangle& t : triangles) {
                bool any = false;
                for (int k = 0; k < 3 && !any; ++k) any = marked.count(edgeKey(t[k], t[(k + 1) % 3])) > 0;
                if (!any) continue;
                int k = longestEdge(positions, t);
                grew |= marked.emplace(edgeKey(t[k], t[(k + 1) % 3]), 0).second;
            }
        }
        // 3. Midpoints, once per edge.
        for (auto& [edge, mid] : marked) {
            mid = static_cast<uint32_t>(positions.size());
            positions.push_back(0.5 * (positions[edge.first] + positions[edge.second]));
        }
        // 4. Split: the longest edge (a, b) at m toward the opposite corner c, then each
        // half again at its marked edge (b, c) or (c, a). Winding is kept.
        std::vector<Triangle> next;
        next.reserve(2 * triangles.size());
        std::vector<uint32_t> nextParents;  // the input triangle each of `next` lies in
        auto midpoint = [&](uint32_t a, uint32_t b) {
            auto it = marked.find(edgeKey(a, b));
            return it == marked.end() ? UINT32_MAX : it->second;
        };
        auto splitHalf = [&](uint32_t p, uint32_t q, uint32_t r) {
            // Half (p, q, r) where (p, q) is an original edge of the parent and r the new
            // midpoint; split it at (p, q)'s midpoint toward r if that edge is marked.
            uint32_t s = midpoint(p, q);
            if (s == UINT32_MAX) {
                next.push_back({p, q, r});
            } else {
                next.push_back({p, s, r});
                next.push_back({s, q, r});
            }
        };
        for (size_t i = 0; i < triangles.size(); ++i) {
            const Triangle& t = triangles[i];
            int k = longestEdge(positions, t);
            uint32_t a = t[k], b = t[(k + 1) % 3], c = t[(k + 2) % 3];
            uint32_t m = midpoint(a, b);
            if (m == UINT32_MAX) {
                next.push_back(t);
            } else {
                // (a, b, c) → (a, m, c) + (m, b, c); their outer edges are (c, a) and (b, c).
                splitHalf(c, a, m);
                splitHalf(b, c, m);
            }
            if (parents) nextParents.resize(next.size(), (*parents)[i]);
        }
        triangles = std::move(next);
        if (parents) *parents = std::move(nextParents);
    }
}

}  // namespace rayrad::radiosity
