#include <radiosity/display/edge_vertices.h>

#include <radiosity/display/contact_vertices.h>
#include <radiosity/display/extrapolated_vertices.h>
#include <radiosity/display/rim_vertices.h>
#include <radiosity/form_factors/form_factor.h>
#include <radiosity/gather/gather.h>
#include <radiosity/mesh/covered_patches.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <map>
#include <tuple>
#include <unordered_map>

#include <tbb/parallel_for.h>

namespace rayrad::radiosity {

namespace {
/// Clusters beyond this many of their diameters count as one source in vertex gathers.
constexpr double kFarClusterDiameters = 3.0;
/// Sub-triangle refinement toward a vertex: as deep as for sensors (at 6 levels the
/// Cornell box's floor vertices along the red wall came out 40 % low).
constexpr int kMaxSplitDepth = 12;

/// The seam vertices (see gatherEdgeVertices) and, per mesh vertex, the patch whose
/// surface it is gathered on (−1 for a vertex of no patch). Its cell index lives only here.
std::vector<size_t> seamVertices(const scene::Scene& scene, const PatchMesh& mesh, const RadiositySolution& solution,
                                 std::vector<int64_t>& patchOf) {
    // One patch per vertex gives its surface (normal, group; vertices are per group) and
    // the side the gather point moves to: the brightest patch around the vertex, so a
    // floor vertex at the foot of a box gathers on the lit side, not under the box.
    patchOf.assign(mesh.vertices.size(), -1);
    std::vector<double> brightness(mesh.vertices.size(), -1.0);
    for (size_t i = 0; i < mesh.patches.size(); ++i) {
        double e = luminance(solution.directMean[i] + solution.indirect[i]);
        for (uint32_t v : mesh.patches[i].v)
            if (e > brightness[v]) brightness[v] = e, patchOf[v] = static_cast<int64_t>(i);
    }

    // Patches by size class and cell, to find a vertex's neighbours without scanning
    // every patch: a patch touching a vertex has its centroid within 1.5 of its
    // diameters. Class k holds the patches with 1.5 d ≤ cell_k = cell_0 · 2^k, in a grid of
    // that cell, so the 27 cells around a vertex hold every such patch of the class.
    double smallest = std::numeric_limits<double>::infinity();
    for (const Patch& p : mesh.patches)
        if (p.diameter > 0) smallest = std::min(smallest, p.diameter);
    const double cell0 =
        std::max(std::isfinite(smallest) ? 1.5 * smallest : 0.0, 1e-9 * std::max(scene.diagonal(), 1e-300));
    auto classOf = [&](double diameter) {
        int k = 0;
        while (1.5 * diameter > std::ldexp(cell0, k)) ++k;
        return k;
    };
    using Key = std::tuple<int, int64_t, int64_t, int64_t>;  // class, cell
    auto keyOf = [&](int k, const Vec3& p) {
        const double cell = std::ldexp(cell0, k);
        auto c = [&](int a) { return static_cast<int64_t>(std::floor((p[a] - scene.boundsMin[a]) / cell)); };
        return Key{k, c(0), c(1), c(2)};
    };
    std::map<Key, std::vector<uint32_t>> byCell;
    std::vector<char> classUsed;
    for (uint32_t j = 0; j < mesh.patches.size(); ++j) {
        const int k = classOf(mesh.patches[j].diameter);
        if (k >= static_cast<int>(classUsed.size())) classUsed.resize(k + 1, 0);
        classUsed[k] = 1;
        byCell[keyOf(k, mesh.patches[j].centroid)].push_back(j);
    }
    const int classes = static_cast<int>(classUsed.size());

    const double nudge = pointNudge(scene);
    const double seamTolerance = 1e-6 * scene.diagonal();
    std::vector<size_t> edge;
    for (size_t v = 0; v < mesh.vertices.size(); ++v) {
        if (patchOf[v] < 0) continue;
        const Patch& own = mesh.patches[patchOf[v]];
        const Vec3 x = nudgeInside(mesh, patchOf[v], mesh.vertices[v], nudge);
        // A seam: the vertex lies on a patch of another surface that x sees — on its edge
        // (a room's corner, mesh lines meeting) or inside it (the foot of a box standing
        // on a floor whose mesh lines run elsewhere). Inside, only where the vertex's own
        // patch is one the premesher made (kContactMinEdges, as for contact outlines): the
        // feet of an input mesh's small parts (a sofa's legs) have bands narrower than half
        // a patch (the living room: 455 feet vertices on such patches, 970 without the bound,
        // beside 674 on edges).
        const Vec3& y = mesh.vertices[v];
        const bool largeOwn = own.diameter >= kContactMinEdges * mesh.edgeLength;
        auto seamWith = [&](uint32_t j) {
            const Patch& p = mesh.patches[j];
            if (p.group == own.group || glm::length(p.centroid - x) > 1.5 * p.diameter) return false;
            Vec3 tri[3] = {mesh.corner(p, 0), mesh.corner(p, 1), mesh.corner(p, 2)};
            if (std::abs(glm::dot(y - tri[0], p.normal)) > seamTolerance) return false;
            bool onPatch = false;
            for (int e = 0; e < 3; ++e)
                onPatch |= glm::length(y - closestOnSegment(y, tri[e], tri[(e + 1) % 3])) <= seamTolerance;
            if (!onPatch && largeOwn) {
                const Vec3 w = barycentric(tri[0], tri[1], tri[2], y);
                onPatch = w[0] >= 0 && w[1] >= 0 && w[2] >= 0;
            }
            return onPatch && formFactorToPolygon(x, own.normal, tri, 3, p.normal) > 0;
        };
        bool isEdge = false;
        for (int k = 0; k < classes && !isEdge; ++k) {
            if (!classUsed[k]) continue;
            const auto [c, hx, hy, hz] = keyOf(k, x);
            for (int64_t dx = -1; dx <= 1 && !isEdge; ++dx)
                for (int64_t dy = -1; dy <= 1 && !isEdge; ++dy)
                    for (int64_t dz = -1; dz <= 1 && !isEdge; ++dz) {
                        auto it = byCell.find({c, hx + dx, hy + dy, hz + dz});
                        if (it != byCell.end()) isEdge = std::any_of(it->second.begin(), it->second.end(), seamWith);
                    }
        }
        if (isEdge) edge.push_back(v);
    }
    return edge;
}

}  // namespace

GatheredVertices gatherEdgeVertices(const scene::Scene& scene, const PatchMesh& mesh, const Clustering& clustering,
                                    RadiositySolution& solution, const Visibility& vis, int levels,
                                    const std::function<void(double)>& onProgress) {
    std::vector<int64_t> patchOf;
    const double nudge = pointNudge(scene);
    // The seams, gathered where they are (nudged into their brightest patch), and the
    // vertices beside an outline crossing their patches that are not seams.
    std::vector<GatherPoint> points;
    std::vector<char> taken(mesh.vertices.size(), 0);
    for (size_t v : seamVertices(scene, mesh, solution, patchOf)) {
        points.push_back({v, nudgeInside(mesh, static_cast<size_t>(patchOf[v]), mesh.vertices[v], nudge),
                          mesh.patches[patchOf[v]].normal});
        taken[v] = 1;
    }
    const size_t seams = points.size();
    const double minDiameter = kContactMinEdges * mesh.edgeLength;
    for (const GatherPoint& g : contactVertices(mesh, patchOf, minDiameter, nudge))
        if (!taken[g.vertex]) points.push_back(g), taken[g.vertex] = 1;
    const size_t contacts = points.size() - seams;
    const double lift = kCoverLift * scene.diagonal();
    // The rims of covered parts (a lamp hung just below a ceiling): their reconstruction
    // has the open side's centroids only, all on one side. Gathered once, like the contacts,
    // and bounded alike (patches at least half the premesher's edge across: in the living
    // room 7 173 rim vertices without the bound).
    for (const GatherPoint& g : rimVertices(mesh, vis, patchOf, taken, minDiameter, nudge, lift))
        points.push_back(g), taken[g.vertex] = 1;
    const size_t rims = points.size() - seams - contacts;
    // Where the reconstruction extrapolated far beyond the patches around a vertex (a
    // face a few patches wide): gathered once, too.
    for (const GatherPoint& g : extrapolatedVertices(mesh, solution, patchOf, taken, minDiameter, nudge))
        points.push_back(g);
    // A vertex of an open patch gathered under a cover (a pane's corner under the lip of its
    // frame) takes the light where its patch is seen.
    const std::vector<char> moved = openGatherPoints(mesh, vis, patchOf, points, lift);

    // A local fixed-point iteration, bottom-up: each round gathers at every seam vertex
    // with the previous round's values at the corners of near patches (the reconstruction
    // to start with, and for corners outside the set). Only the near patches' part of a
    // gather depends on those values: the rest is gathered once, in the first round, and
    // kept. A vertex beside an outline or on a cover's rim is gathered in the first round
    // only (and so is an extrapolated one): its near patches are the standing surface's,
    // whose corners the rounds do not change (on the
    // Cornell floor three rounds and one give the same errors, within 0.1 %). Parallel
    // over vertices; each gather serial, so the result does not depend on the thread count.
    GatherOptions options = GatherOptions::plain();
    options.gatherLevels = levels;
    options.gatherFarDiameters = kFarClusterDiameters;
    options.maxSplitDepth = kMaxSplitDepth;
    Gatherer gatherer(scene, mesh, clustering, solution, vis, options);
    std::unordered_map<uint32_t, size_t> slot;
    for (size_t k = 0; k < points.size(); ++k) slot.emplace(static_cast<uint32_t>(points[k].vertex), k);
    std::vector<Rgb> previous(points.size()), current(points.size());
    std::vector<Rgb> rest(points.size());  // lx: each vertex's gather but for its near patches
    for (size_t k = 0; k < points.size(); ++k) previous[k] = solution.vertexIndirect[points[k].vertex];
    Gatherer::CornerSource corners = [&](size_t patch, int corner, double /*share*/) {
        uint32_t v = mesh.patches[patch].v[corner];
        auto it = slot.find(v);
        return it != slot.end() ? previous[it->second] : solution.vertexIndirect[v];
    };
    std::atomic<size_t> done{0};
    const double total = static_cast<double>(seams) * levels + static_cast<double>(points.size() - seams);
    // Each point's near patches, found once for its two parts and its rounds (the search
    // visits every cluster).
    std::vector<std::vector<uint32_t>> nearSets(points.size());
    for (int round = 0; round < levels; ++round) {
        tbb::parallel_for(size_t(0), points.size(), [&](size_t k) {
            const GatherPoint& g = points[k];
            using Part = Gatherer::Part;
            if (round > 0 && k >= seams) {  // beside an outline: one round
                current[k] = previous[k];
                return;
            }
            if (round == 0) {
                nearSets[k] = gatherer.nearPatches({g.at, g.at});
                Gatherer::Request far(g.at, g.normal, &corners, Gatherer::Threads::Serial);
                far.part = Part::AllButNear;
                far.expected = luminance(solution.vertexIndirect[g.vertex]);
                far.nearSet = &nearSets[k];
                rest[k] = gatherer.gatherWith(far);
            }
            Gatherer::Request near(g.at, g.normal, &corners, Gatherer::Threads::Serial);
            near.part = Part::Near;
            near.nearSet = &nearSets[k];
            current[k] = rest[k] + gatherer.gatherWith(near);
            if (round + 1 == levels || k >= seams) std::vector<uint32_t>().swap(nearSets[k]);  // not needed again
            size_t n = ++done;
            if (onProgress && n % 16 == 0) onProgress(static_cast<double>(n) / total);
        });
        std::swap(previous, current);
    }
    for (size_t k = 0; k < points.size(); ++k) solution.vertexIndirect[points[k].vertex] = previous[k];
    GatheredVertices out{seams, contacts, rims, points.size() - seams - contacts - rims, {}, {}};
    for (size_t k = 0; k < seams; ++k) {
        out.seamVertices.push_back(static_cast<uint32_t>(points[k].vertex));
        if (moved[k]) out.seamsGatheredAside.push_back(static_cast<uint32_t>(points[k].vertex));
    }
    std::sort(out.seamVertices.begin(), out.seamVertices.end());
    std::sort(out.seamsGatheredAside.begin(), out.seamsGatheredAside.end());
    return out;
}

}  // namespace rayrad::radiosity
