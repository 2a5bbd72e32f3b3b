#include <radiosity/clusters/image_clusters.h>
#include <radiosity/gather/gather.h>
#include <radiosity/gather/gather_parts.h>
#include <radiosity/mesh/patch_reflectance.h>

#include <radiosity/gather/visibility_share.h>
#include <radiosity/mesh/small_meshes.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace rayrad::radiosity {

namespace {
/// A source patch is "near" x within this many diameters of its centroid.
constexpr double kNearDiameters = 2.0;
/// Members per leaf of the far-field member trees.
constexpr size_t kFarLeafSize = 8;
/// The sensor gather's sliver width as a share of the premesher's edge (GatherOptions::
/// minRefineWidth): a premeshed right triangle is 0.71 of its edge wide, so only an input
/// mesh's own slivers are narrower.
constexpr double kSliverEdges = 0.05;
}  // namespace

GatherOptions GatherOptions::forSensors(const scene::Scene& scene, const PatchMesh& mesh) {
    GatherOptions o;
    static_cast<scene::GatherOptions&>(o) = scene.gather;
    o.minRefineWidth = kSliverEdges * mesh.edgeLength;
    o.parallelSums = !tooSmallToShare(mesh);
    return o;
}

GatherOptions GatherOptions::plain() {
    GatherOptions o;  // the tolerance stays the scene's default: it acts only with refinement levels
    o.gatherLevels = 0;
    o.gatherRefineLevels = 0;
    o.gatherFarDiameters = 0;
    o.gatherMinWeight = 0;
    return o;
}

Gatherer::Gatherer(const scene::Scene& scene, const PatchMesh& mesh, const Clustering& clustering,
                   const RadiositySolution& solution, const Visibility& vis, const GatherOptions& options)
    : m_scene(scene),
      m_mesh(mesh),
      m_clustering(clustering),
      m_solution(solution),
      m_vis(vis),
      m_options(options),
      m_nudge(pointNudge(scene)) {
    m_treePosition.resize(mesh.patches.size());
    for (const auto& C : clustering.clusters) {
        double size = 0;
        for (uint32_t j : C.patches) size = std::max(size, mesh.patches[j].diameter);
        m_clusterPatchSize.push_back(size);
        MemberTree tree = memberTree(mesh, C, kFarLeafSize);
        for (uint32_t i = 0; i < tree.order.size(); ++i) m_treePosition[C.patches[tree.order[i]]] = i;
        std::vector<Rgb> luminance(C.patches.size());
        for (size_t k = 0; k < C.patches.size(); ++k)
            luminance[k] = solution.reflectedLuminance(scene, mesh, C.patches[k]);
        m_far.push_back(farSources(mesh, C, tree, luminance, FarRayTargets::PowerSamples));
        m_rootFar.push_back(m_far.back().front());
        m_trees.push_back(std::move(tree));
    }
    m_groupCone = glm::radians(scene.clusters.normalToleranceDeg);
    // Groups of clusters only where there are clusters: without them the gather, as the
    // transfers, does not depend on the light (light groups' parts then add up exactly).
    if (clustering.enabled)
        m_clusterTree = clusterTree(mesh, clustering, m_rootFar,
                                    [&](uint32_t j) { return solution.reflectedLuminance(scene, mesh, j); });
    m_mirrorViews = mirrorViewsFor(scene, vis);
    m_sourceKeys.push_back(0);
    for (const auto& view : m_mirrorViews) {
        m_sourceKeys.push_back(imageKey(view->image.chain));
        m_imageSends.push_back(clustersFacing(scene.mirrors[view->image.chain.front()], mesh, clustering));
    }
    m_regions = voxelRegions(clustering);
}

Rgb Gatherer::solutionCorner(size_t patch, int corner) const {
    if (m_solution.vertexIndirect.empty()) return m_solution.indirect[patch];
    return m_solution.vertexIndirect[m_mesh.patches[patch].v[corner]];
}

int Gatherer::classOf(double weight) const {
    if (m_options.gatherMinWeight <= 0 || weight >= 1) return 0;
    return static_cast<int>(std::floor(-std::log10(weight)));
}

const Rgb* GatherMemo::recall(const std::map<Key, Entry>& memo, const Key& key, int weightClass) {
    // The id's entries are contiguous, in increasing level.
    for (auto it = memo.lower_bound(key); it != memo.end() && it->first.first == key.first; ++it)
        if (it->second.weightClass <= weightClass) return &it->second.indirect;
    return nullptr;
}

Rgb Gatherer::cornerIndirect(size_t patch, int corner, int level, int weightClass, GatherMemo& memo) const {
    // Below the re-gathers, the solution's own value there: what its display shows.
    if (level <= 0) return solutionCorner(patch, corner);
    const uint32_t v = m_mesh.patches[patch].v[corner];
    const GatherMemo::Key key{v, level};
    if (const Rgb* known = GatherMemo::recall(memo.m_vertex, key, weightClass)) return *known;
    const Patch& p = m_mesh.patches[patch];
    Rgb e = gather(nudgeInside(m_mesh, patch, m_mesh.vertices[v], m_nudge), p.normal, level, weightClass, memo);
    memo.m_vertex[key] = {e, weightClass};
    return e;
}

Gatherer::Midpoint Gatherer::midpointIndirect(size_t patch, uint64_t a, uint64_t b, const Vec3& y, int level,
                                              int weightClass, GatherMemo& memo) const {
    // Ids above the mesh's vertex indices.
    const uint64_t firstId = uint64_t(1) << 32;
    auto [idAt, added] =
        memo.m_midpointIds.emplace(std::make_pair(std::min(a, b), std::max(a, b)), firstId + memo.m_midpointIds.size());
    const uint64_t id = idAt->second;
    if (level <= 0) {  // below the re-gathers: the display's value, seam profiles included
        if (m_solution.vertexIndirect.empty()) return {id, m_solution.indirect[patch]};
        const Patch& p = m_mesh.patches[patch];
        const Vec3 w = barycentric(m_mesh.vertices[p.v[0]], m_mesh.vertices[p.v[1]], m_mesh.vertices[p.v[2]], y);
        return {id, interpolateIndirect(m_mesh, m_solution, patch, w[1], w[2])};
    }
    const GatherMemo::Key key{id, level};
    if (const Rgb* known = GatherMemo::recall(memo.m_midpoint, key, weightClass)) return {id, *known};
    Rgb e = gather(nudgeInside(m_mesh, patch, y, m_nudge), m_mesh.patches[patch].normal, level, weightClass, memo);
    memo.m_midpoint[key] = {e, weightClass};
    return {id, e};
}

std::vector<uint32_t> Gatherer::nearPatches(const Segment& along) const {
    std::vector<uint32_t> out;
    auto offset = [&](const Vec3& y) { return y - closestOnSegment(y, along.a, along.b); };
    for (size_t c = 0; c < m_clustering.clusters.size(); ++c) {
        const Cluster& C = m_clustering.clusters[c];
        // Only clusters that can hold a patch within kNearDiameters of the segment.
        const double reach = 0.5 * C.diameter + kNearDiameters * m_clusterPatchSize[c];
        const Vec3 dc = offset(C.centroid);
        if (glm::dot(dc, dc) > reach * reach) continue;
        for (uint32_t j : C.patches) {
            const Patch& p = m_mesh.patches[j];
            const double r = kNearDiameters * p.diameter;
            const Vec3 d = offset(p.centroid);
            if (glm::dot(d, d) <= r * r) out.push_back(j);
        }
    }
    return out;
}

Rgb Gatherer::gather(const Vec3& x, const Vec3& n, int level, int weightClass, GatherMemo& memo,
                     double expected) const {
    ++memo.m_gathers;
    // This gather's error reaches the sensor with weight w; a near patch's corners and
    // midpoints with w ρ F. Those below the minimum weight are not worth a gather.
    const double weight = std::pow(10.0, -weightClass);
    Request request;
    request.x = x, request.n = n, request.weight = weight, request.expected = expected;
    request.threads = m_options.parallelSums ? Threads::Parallel : Threads::Serial;
    if (level <= 0) return gatherWith(request);
    // The memo is filled while the near list is built (serially); the sum runs in parallel.
    CornerSource corners = [&](size_t patch, int corner, double share) {
        return cornerIndirect(patch, corner, level - 1, classOf(weight * share), memo);
    };
    request.corners = &corners;
    if (level <= m_options.gatherLevels - m_options.gatherRefineLevels) return gatherWith(request);
    MidpointSource midpoints = [&](size_t patch, uint64_t a, uint64_t b, const Vec3& y, double share) {
        return midpointIndirect(patch, a, b, y, level - 1, classOf(weight * share), memo);
    };
    request.midpoints = &midpoints;
    return gatherWith(request);
}

Rgb Gatherer::gatherWith(const Request& request) const {
    NearField near;
    if (request.corners) findNearField(request, near);
    if (request.part == Part::Near) {
        Rgb sum(0.0);
        for (const NearPatch& e : near.patches) addNear(request, near, e, sum);
        return sum;
    }
    const PointSources point = pointSources(request, near);
    return sumSources(point, sceneItems(point));
}

}  // namespace rayrad::radiosity
