// The gather's near field: the patches beside the point, their luminance linear between
// corner values, refined toward the point with gathered midpoints where it is not linear
// enough, and integrated exactly where the point sees a piece whole (see Gatherer).
#include <radiosity/gather/gather_parts.h>
#include <radiosity/mesh/patch_reflectance.h>

#include <radiosity/form_factors/form_factor.h>
#include <radiosity/form_factors/form_factor_centroid.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace rayrad::radiosity {

namespace {
/// Sub-triangles are split while closer to x than this many of their own sizes: for
/// integration (π L(centroid) F with the analytic F, and one visibility ray, per piece)
/// and for refinement with gathered midpoints. 2 cost the cube's 1 024-sensor grid 2.6 x
/// the pieces and 1.7 x the gathers of 1 for the same accuracy (docs/validation.md).
constexpr double kSplitRatio = 1.0;
/// Near triangles are split at most this deep with gathered midpoints (then linearly).
constexpr int kRefineDepth = 6;
/// Near patches holding at least 1/kRefineShares of the near field's ρ F are refined to
/// the full tolerance; smaller ones to a tolerance looser in proportion.
constexpr double kRefineShares = 20;
}  // namespace

void Gatherer::addNear(const Request& request, const NearField& near, const NearPatch& e, Rgb& into) const {
    for (uint32_t k = e.first; k < e.first + e.count; ++k) {
        const NearPiece& piece = near.pieces[k];
        into += integrateLinear(request.x, request.n, piece.p.data(), piece.L.data(), m_mesh.patches[e.patch].normal,
                                piece.depth, e.known(piece));
    }
}

void Gatherer::findNearField(const Request& request, NearField& near) const {
    const Vec3& x = request.x;
    const Vec3& n = request.n;
    // The near patches that face x, in cluster order.
    struct Candidate {
        uint32_t cluster, patch;
        double share;  ///< ρ F: how much of an error in its corner values reaches x
        double F;
    };
    std::vector<Candidate> candidates;
    // Near to x, or the set asked for (in cluster order either way).
    const std::vector<uint32_t> nearX = request.nearSet ? std::vector<uint32_t>() : nearPatches({x, x});
    for (uint32_t j : request.nearSet ? *request.nearSet : nearX) {
        const Patch& p = m_mesh.patches[j];
        const Rgb rho = patchReflectance(m_scene, m_mesh, j);
        if (rho == Rgb(0.0)) continue;
        const Vec3 v[3] = {m_mesh.corner(p, 0), m_mesh.corner(p, 1), m_mesh.corner(p, 2)};
        const double F = formFactorToPolygon(x, n, v, 3, p.normal);
        if (F > 0) candidates.push_back({m_clustering.clusterOf[j], j, std::max({rho[0], rho[1], rho[2]}) * F, F});
    }
    // The smallest shares whose sum stays within the floor keep the solution's corner
    // values: what their error can bring to x is bounded by the floor, whatever their number.
    double shareSum = 0;
    for (const Candidate& e : candidates) shareSum += e.share;
    double detailFrom = 0;  // shares from here on are gathered
    const double weight = request.weight;
    const double detailFloor = m_options.gatherMinWeight > 0 ? m_options.gatherMinWeight / weight : 0;
    if (detailFloor > 0) {
        std::vector<double> shares;
        for (const Candidate& e : candidates) shares.push_back(e.share);
        std::sort(shares.begin(), shares.end());
        double pruned = 0;
        for (double share : shares) {
            if (pruned + share > detailFloor) break;
            pruned += share;
            detailFrom = std::nextafter(share, 2.0);
        }
    }
    for (const Candidate& e : candidates) {
        const uint32_t j = e.patch;
        if (near.clusters.empty() || near.clusters.back().cluster != e.cluster)
            near.clusters.push_back({e.cluster, near.patches.size(), near.patches.size()});
        near.patches.push_back({j, m_treePosition[j], 0, 0, e.F});
        near.clusters.back().end = near.patches.size();
        if (request.part == Part::AllButNear) continue;  // which patches are near is all it needs
        const Patch& p = m_mesh.patches[j];
        const Rgb rho = patchReflectance(m_scene, m_mesh, j);
        const bool sliver = 2 * p.area < m_options.minRefineWidth * p.diameter;
        const bool detailed = e.share >= detailFrom;
        std::array<RefinePoint, 3> corners;
        for (int k = 0; k < 3; ++k) {
            const Rgb E(m_solution.directCorner[3 * j + k]);
            const Rgb indirect = detailed ? (*request.corners)(j, k, e.share) : solutionCorner(j, k);
            corners[k] = {m_mesh.corner(p, k), p.v[k], rho * (E + indirect) / kPi, E};
        }
        // A piece is refined while its midpoints depart from linear by more than the
        // tolerance; patches holding less than 1/kRefineShares of the near field's share
        // may depart more, in proportion (400 slivers of a sofa do not each need it), and
        // so may a gather whose error reaches the sensor with weight w < 1, by 1/w.
        const double tolerance = m_options.gatherRefineTolerance * std::max(1.0, shareSum / (kRefineShares * e.share)) /
                                 (m_options.gatherMinWeight > 0 ? weight : 1.0);
        const size_t first = near.pieces.size();
        refineNear(x, j, corners, 0, detailed && !sliver ? request.midpoints : nullptr, e.share, tolerance,
                   near.pieces);
        near.patches.back().first = static_cast<uint32_t>(first);
        near.patches.back().count = static_cast<uint32_t>(near.pieces.size() - first);
    }
    for (const NearCluster& c : near.clusters)
        std::sort(near.patches.begin() + static_cast<std::ptrdiff_t>(c.begin),
                  near.patches.begin() + static_cast<std::ptrdiff_t>(c.end),
                  [](const NearPatch& a, const NearPatch& b) { return a.position < b.position; });
}

void Gatherer::refineNear(const Vec3& x, size_t patch, const std::array<RefinePoint, 3>& c, int depth,
                          const MidpointSource* midpoints, double share, double tolerance,
                          std::vector<NearPiece>& pieces) const {
    const Vec3 &p0 = c[0].p, &p1 = c[1].p, &p2 = c[2].p;
    double size = std::max({glm::length(p1 - p0), glm::length(p2 - p1), glm::length(p0 - p2)});
    Vec3 centroid = (p0 + p1 + p2) / 3.0;
    double dist = std::min({glm::length(centroid - x), glm::length(p0 - x), glm::length(p1 - x), glm::length(p2 - x)});
    if (!midpoints || depth >= kRefineDepth || dist >= kSplitRatio * size) {
        pieces.push_back({{p0, p1, p2}, {c[0].L, c[1].L, c[2].L}, depth});
        return;
    }
    // Midpoint m[k] of edge (k, k+1): L = ρ (E_dir + E_ind) / π, E_dir interpolated, E_ind gathered.
    const Rgb rho = patchReflectance(m_scene, m_mesh, patch);
    std::array<RefinePoint, 3> m;
    double worst = 0;  // largest relative difference from the linear interpolation
    for (int k = 0; k < 3; ++k) {
        const RefinePoint &a = c[k], &b = c[(k + 1) % 3];
        const Vec3 y = 0.5 * (a.p + b.p);
        const Midpoint g = (*midpoints)(patch, a.id, b.id, y, share);
        const Rgb E = 0.5 * (a.E + b.E);
        m[k] = {y, g.id, rho * (E + g.indirect) / kPi, E};
        double linear = luminance(0.5 * (a.L + b.L));
        if (linear > 0) worst = std::max(worst, std::abs(luminance(m[k].L) / linear - 1));
    }
    // Linear enough here: the pieces go on splitting toward x with interpolated values.
    const MidpointSource* deeper = worst >= tolerance ? midpoints : nullptr;
    refineNear(x, patch, {c[0], m[0], m[2]}, depth + 1, deeper, share, tolerance, pieces);
    refineNear(x, patch, {m[0], c[1], m[1]}, depth + 1, deeper, share, tolerance, pieces);
    refineNear(x, patch, {m[2], m[1], c[2]}, depth + 1, deeper, share, tolerance, pieces);
    refineNear(x, patch, {m[0], m[1], m[2]}, depth + 1, deeper, share, tolerance, pieces);
}

Rgb Gatherer::integrateLinear(const Vec3& x, const Vec3& n, const Vec3 p[3], const Rgb L[3], const Vec3& normal,
                              int depth, double knownF) const {
    const VertexView view[3] = {viewFrom(x, p[0]), viewFrom(x, p[1]), viewFrom(x, p[2])};
    return integrateLinear(x, n, p, view, L, normal, depth, knownF, /*wholeIfSeen=*/true);
}

bool Gatherer::seenWhole(const Vec3& x, const Vec3& n, const Vec3 p[3], const Vec3& lightCentre) const {
    // Where its light comes from first (the likeliest to be hidden), then a point toward
    // each corner (barycentrics 2/3, 1/6, 1/6); points behind x's plane send nothing and
    // are not asked.
    const Vec3 targets[4] = {lightCentre, (4.0 * p[0] + p[1] + p[2]) / 6.0, (p[0] + 4.0 * p[1] + p[2]) / 6.0,
                             (p[0] + p[1] + 4.0 * p[2]) / 6.0};
    for (const Vec3& y : targets)
        if (glm::dot(y - x, n) > 0 && !m_vis.visibleFromSurface(x, n, y)) return false;
    return true;
}

Rgb Gatherer::integrateLinear(const Vec3& x, const Vec3& n, const Vec3 p[3], const VertexView view[3], const Rgb L[3],
                              const Vec3& normal, int depth, double knownF, bool wholeIfSeen) const {
    Vec3 c = (p[0] + p[1] + p[2]) / 3.0;
    double size = std::max({glm::length(p[1] - p[0]), glm::length(p[2] - p[1]), glm::length(p[0] - p[2])});
    double dist = std::min({glm::length(c - x), view[0].r, view[1].r, view[2].r});
    const bool close = depth < m_options.maxSplitDepth && dist < kSplitRatio * size;
    if (close && wholeIfSeen) {
        // Wholly seen, a close piece needs no split: its linear luminance integrates exactly,
        // E = π F L(c_F) (form_factor_centroid.h). Partly hidden, it is split as below, and
        // its pieces are not asked again.
        const FormFactorCentroid light = formFactorCentroid(x, n, p, 3, normal);
        if (!(light.F > 0)) return Rgb(0.0);
        if (seenWhole(x, n, p, light.centroid)) {
            // c_F lies in the triangle: barycentrics outside it are rounding, clamped.
            Vec3 w = glm::max(barycentric(p[0], p[1], p[2], light.centroid), Vec3(0.0));
            w /= w[0] + w[1] + w[2];
            return (w[0] * L[0] + w[1] * L[1] + w[2] * L[2]) * (kPi * light.F);
        }
    }
    if (close) {
        // Each new vertex is seen from x once, for the two or three children it is a corner of.
        Vec3 m01 = 0.5 * (p[0] + p[1]), m12 = 0.5 * (p[1] + p[2]), m20 = 0.5 * (p[2] + p[0]);
        const VertexView v01 = viewFrom(x, m01), v12 = viewFrom(x, m12), v20 = viewFrom(x, m20);
        Rgb l01 = 0.5 * (L[0] + L[1]), l12 = 0.5 * (L[1] + L[2]), l20 = 0.5 * (L[2] + L[0]);
        const Vec3 t[4][3] = {{p[0], m01, m20}, {m01, p[1], m12}, {m20, m12, p[2]}, {m01, m12, m20}};
        const VertexView tv[4][3] = {{view[0], v01, v20}, {v01, view[1], v12}, {v20, v12, view[2]}, {v01, v12, v20}};
        const Rgb l[4][3] = {{L[0], l01, l20}, {l01, L[1], l12}, {l20, l12, L[2]}, {l01, l12, l20}};
        Rgb sum(0.0);
        for (int k = 0; k < 4; ++k) sum += integrateLinear(x, n, t[k], tv[k], l[k], normal, depth + 1, -1, false);
        return sum;
    }
    const double f = knownF >= 0 ? knownF : formFactorToTriangle(x, n, p, view, normal);
    if (f <= 0 || !m_vis.visibleFromSurface(x, n, c)) return Rgb(0.0);
    return (L[0] + L[1] + L[2]) / 3.0 * (kPi * f);  // E = π L(centroid) F
}

}  // namespace rayrad::radiosity
