#include <radiosity/edge_vertices.h>

#include <radiosity/form_factor.h>
#include <radiosity/gather.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <map>
#include <unordered_map>

#include <tbb/parallel_for.h>

namespace rayrad::radiosity {

namespace {
/// Clusters beyond this many of their diameters count as one source in vertex gathers.
constexpr double kFarClusterDiameters = 3.0;
/// Sub-triangle refinement toward a vertex: as deep as for sensors (at 6 levels the
/// Cornell box's floor vertices along the red wall came out 40 % low).
constexpr int kMaxSplitDepth = 12;

/// Distance (m) from point p to the segment ab.
double distanceToSegment(const Vec3& p, const Vec3& a, const Vec3& b) {
    Vec3 ab = b - a;
    double t = std::clamp(glm::dot(p - a, ab) / std::max(glm::dot(ab, ab), 1e-300), 0.0, 1.0);
    return glm::length(p - (a + t * ab));
}
}  // namespace

size_t gatherEdgeVertices(const scene::Scene& scene, const PatchMesh& mesh, const Clustering& clustering,
                          RadiositySolution& solution, const Visibility& vis, int levels,
                          const std::function<void(double)>& onProgress) {
    // One patch per vertex gives its surface (normal, group; vertices are per group) and
    // the side the gather point moves to: the brightest patch around the vertex, so a
    // floor vertex at the foot of a box gathers on the lit side, not under the box.
    std::vector<int64_t> patchOf(mesh.vertices.size(), -1);
    std::vector<double> brightness(mesh.vertices.size(), -1.0);
    for (size_t i = 0; i < mesh.patches.size(); ++i) {
        double e = luminance(solution.directMean[i] + solution.indirect[i]);
        for (uint32_t v : mesh.patches[i].v)
            if (e > brightness[v]) brightness[v] = e, patchOf[v] = static_cast<int64_t>(i);
    }

    // Clusters by voxel, to find a vertex's neighbours without scanning every patch.
    std::map<std::array<int, 3>, std::vector<uint32_t>> byVoxel;
    for (uint32_t c = 0; c < clustering.clusters.size(); ++c) byVoxel[clustering.clusters[c].voxel].push_back(c);
    auto voxelOf = [&](const Vec3& p) {
        std::array<int, 3> v;
        for (int a = 0; a < 3; ++a)
            v[a] = std::clamp(static_cast<int>(std::floor((p[a] - clustering.origin[a]) / clustering.voxelSize)), 0,
                              clustering.dims[a] - 1);
        return v;
    };

    // How many voxels around a vertex can hold the centroid of a patch touching it.
    double largestDiameter = 0;
    for (const Patch& p : mesh.patches) largestDiameter = std::max(largestDiameter, p.diameter);
    const int reach = static_cast<int>(std::ceil(1.5 * largestDiameter / clustering.voxelSize));

    const double nudge = 1e-6 * scene.diagonal();
    const double seamTolerance = 1e-6 * scene.diagonal();
    std::vector<size_t> edge;
    for (size_t v = 0; v < mesh.vertices.size(); ++v) {
        if (patchOf[v] < 0) continue;
        const Patch& own = mesh.patches[patchOf[v]];
        const Vec3 x = nudgeInside(mesh, patchOf[v], mesh.vertices[v], nudge);
        auto home = voxelOf(x);
        bool isEdge = false;
        for (int dx = -reach; dx <= reach && !isEdge; ++dx)
            for (int dy = -reach; dy <= reach && !isEdge; ++dy)
                for (int dz = -reach; dz <= reach && !isEdge; ++dz) {
                    auto it = byVoxel.find({home[0] + dx, home[1] + dy, home[2] + dz});
                    if (it == byVoxel.end()) continue;
                    for (uint32_t c : it->second)
                        for (uint32_t j : clustering.clusters[c].patches) {
                            const Patch& p = mesh.patches[j];
                            if (p.group == own.group || glm::length(p.centroid - x) > 1.5 * p.diameter) continue;
                            Vec3 tri[3] = {mesh.corner(p, 0), mesh.corner(p, 1), mesh.corner(p, 2)};
                            // A seam: the vertex lies on one of the facing patch's edges.
                            bool onSeam = false;
                            for (int e = 0; e < 3; ++e)
                                onSeam |= distanceToSegment(mesh.vertices[v], tri[e], tri[(e + 1) % 3]) <= seamTolerance;
                            if (onSeam && formFactorToPolygon(x, own.normal, tri, 3, p.normal) > 0) {
                                isEdge = true;
                                break;
                            }
                        }
                }
        if (isEdge) edge.push_back(v);
    }

    // A local fixed-point iteration, bottom-up: each round gathers at every edge vertex
    // with the previous round's values at the corners of near patches (the reconstruction
    // to start with, and for corners outside the set). Parallel over vertices; each
    // gather serial, so the result does not depend on the thread count.
    Gatherer gatherer(scene, mesh, clustering, solution, vis, levels, kFarClusterDiameters, kMaxSplitDepth);
    std::unordered_map<uint32_t, size_t> slot;
    for (size_t k = 0; k < edge.size(); ++k) slot.emplace(static_cast<uint32_t>(edge[k]), k);
    std::vector<Rgb> previous(edge.size()), current(edge.size());
    for (size_t k = 0; k < edge.size(); ++k) previous[k] = solution.vertexIndirect[edge[k]];
    Gatherer::CornerSource corners = [&](size_t patch, int corner) {
        uint32_t v = mesh.patches[patch].v[corner];
        auto it = slot.find(v);
        return it != slot.end() ? previous[it->second] : solution.vertexIndirect[v];
    };
    std::atomic<size_t> done{0};
    const double total = static_cast<double>(edge.size()) * levels;
    for (int round = 0; round < levels; ++round) {
        tbb::parallel_for(size_t(0), edge.size(), [&](size_t k) {
            size_t v = edge[k];
            const Patch& own = mesh.patches[patchOf[v]];
            current[k] = gatherer.gatherWith(nudgeInside(mesh, patchOf[v], mesh.vertices[v], nudge), own.normal,
                                             &corners, /*parallel=*/false);
            size_t n = ++done;
            if (onProgress && n % 16 == 0) onProgress(static_cast<double>(n) / total);
        });
        std::swap(previous, current);
    }
    for (size_t k = 0; k < edge.size(); ++k) solution.vertexIndirect[edge[k]] = previous[k];
    return edge.size();
}

}  // namespace rayrad::radiosity
