// The gather's sum over sources: every cluster of the scene (near patches by their pieces,
// other patches with their own rays when close, far clusters with shared rays, far member-tree
// nodes as one source each), in a re-gather far groups of clusters as one, and every mirror
// image's clusters seen through its chain (see Gatherer).
#include <radiosity/gather/gather_parts.h>

#include <core/ray_batch.h>
#include <radiosity/form_factors/patch_transfer.h>

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>  // parallel_deterministic_reduce: same sum for any thread count

#include <algorithm>
#include <cmath>
#include <vector>

namespace rayrad::radiosity {

namespace {
/// A far source whose light at the point is below this share of the indirect illuminance
/// expected there takes one visibility ray, any other four (PointSources::raysFor).
constexpr double kWeakSourceShare = 1e-3;
/// A cluster farther than this many of its diameters shares its visibility rays.
constexpr double kClusterVisibilityDiameters = 2.0;
/// A re-gather of small weight counts nodes as far from this many of their diameters at
/// the least (PointSources::farDiameters).
constexpr double kLeastFarDiameters = 2.0;
/// Where the whole cluster's shared rays fall (visibilityOffset's node for them).
constexpr uint32_t kWholeCluster = (1u << 24) - 1;
}  // namespace

Gatherer::PointSources Gatherer::pointSources(const Request& request, const NearField& near) const {
    PointSources point(request, near);
    const double far = m_options.gatherFarDiameters;
    point.farDiameters =
        far > 0 && request.weight < 1 ? std::max(kLeastFarDiameters, far * std::cbrt(request.weight)) : far;
    point.weakBelow = kWeakSourceShare * request.expected;
    // Per mirror image, which voxels' clusters may send x light through its chain (most do
    // not: a cluster there adds nothing, so skipping it leaves every sum as it was).
    point.regions = m_regions.regions.size();
    point.regionOpen.resize(m_mirrorViews.size() * point.regions);
    for (size_t i = 0; i < m_mirrorViews.size(); ++i) {
        const MirrorImage& image = m_mirrorViews[i]->image;
        // Nothing comes through a chain whose last mirror x does not face.
        if (!m_scene.mirrors[image.chain.back()].facedBy(request.x, request.n)) continue;
        point.sources.push_back(static_cast<uint32_t>(i + 1));
        for (size_t r = 0; r < point.regions; ++r) {
            const VoxelRegions::Region& region = m_regions.regions[r];
            point.regionOpen[i * point.regions + r] =
                image.mayPassToPoint(image.point(region.centre), region.radius, request.x);
        }
    }
    return point;
}

std::vector<uint32_t> Gatherer::sceneItems(const PointSources& point) const {
    // In a re-gather (weight < 1), groups of clusters far from x (ClusterTree), holding no
    // near patch, count as one source each; in the sensor's own gather every cluster is
    // on its own (no items: the sum takes the clusters in order).
    std::vector<uint32_t> items;
    const Vec3& x = point.request.x;
    if (!(point.request.weight < 1 && point.farDiameters > 0 && !m_clusterTree.groups.empty())) return items;
    const size_t clusters = m_clustering.clusters.size();
    std::vector<uint32_t> nearAt;  // tree positions of the clusters holding near patches
    for (const NearCluster& c : point.near.clusters) nearAt.push_back(m_clusterTree.position[c.cluster]);
    std::sort(nearAt.begin(), nearAt.end());
    auto holdsNear = [&](const ClusterGroup& g) {
        auto it = std::lower_bound(nearAt.begin(), nearAt.end(), g.begin);
        return it != nearAt.end() && *it < g.end;
    };
    std::vector<uint32_t> stack{0};
    while (!stack.empty()) {
        const uint32_t index = stack.back();
        stack.pop_back();
        const ClusterGroup& g = m_clusterTree.groups[index];
        if (g.leaf()) {
            items.push_back(m_clusterTree.order[g.begin]);
            continue;
        }
        const double limit = point.farDiameters * g.far.reach;
        if (!g.far.mixed && g.coneAngle <= m_groupCone && glm::dot(g.far.at - x, g.far.at - x) > limit * limit &&
            !holdsNear(g)) {
            items.push_back(static_cast<uint32_t>(clusters + index));
            continue;
        }
        stack.push_back(g.right), stack.push_back(g.left);
    }
    return items;
}

Rgb Gatherer::groupContribution(const PointSources& point, uint32_t index) const {
    // Seen through two visibility rays, four where they disagree.
    const Vec3& x = point.request.x;
    const Vec3& n = point.request.n;
    const ClusterGroup& g = m_clusterTree.groups[index];
    const Rgb e = farField(g.far, x, n, nullptr);
    if (e == Rgb(0.0)) return e;
    auto seen = [&](uint32_t i) { return m_vis.visibleFromSurface(x, n, m_mesh.patches[g.rayPatch[i]].centroid); };
    return e * visibleShare(g.far, seen, VisibilityRays::UpToFour, visibilityOffset(x, 0, (uint64_t(1) << 63) | index));
}

Rgb Gatherer::clusterContribution(const PointSources& point, size_t s, size_t c) const {
    const Request& request = point.request;
    const Vec3& x = request.x;
    const Vec3& n = request.n;
    const bool real = s == 0;
    const MirrorImage* image = real ? nullptr : &m_mirrorViews[s - 1]->image;
    const Cluster& C = m_clustering.clusters[c];  // members mirrored as they are used
    const Visibility& vis = real ? m_vis : *m_mirrorViews[s - 1]->path;
    const Rgb mirrorWeight = real ? Rgb(1.0) : image->weight;  // Π Ks of the chain
    const auto nearRange =
        real ? point.near.of(static_cast<uint32_t>(c)) : std::pair{point.near.patches.end(), point.near.patches.end()};
    const NearField::Iterator nearFirst = nearRange.first, nearLast = nearRange.second;
    const bool hasNear = nearFirst != nearLast;
    const Vec3 centroid = real ? C.centroid : image->point(C.centroid);
    if (!real && !image->mayPassToPoint(centroid, 0.5 * C.diameter, x)) return Rgb(0.0);
    const double d2 = glm::dot(centroid - x, centroid - x);
    const double far = kClusterVisibilityDiameters * C.diameter;
    const bool shared = m_options.sharedRays && C.patches.size() > 1 && d2 > far * far;
    Rgb sum(0.0), sharedSum(0.0);
    // Used only within this call (no gather runs inside it): one per thread is enough.
    thread_local ClusterVisibility sharedVisibility;
    if (shared) sharedVisibility.start(C.patches);
    // Where the ray to patch j goes: its centroid in this source.
    auto rayTarget = [&](uint32_t j) {
        return real ? m_mesh.patches[j].centroid : image->point(m_mesh.patches[j].centroid);
    };
    auto visiblePatch = [&](uint32_t j) { return vis.visibleFromSurface(x, n, rayTarget(j)); };
    // The rays to patches of a cluster that does not share them, traced together.
    RayBatch<Rgb> rays(vis, x, n, sum);
    // The first near patch at or after tree position k.
    auto nearFrom = [&](uint32_t k) {
        return std::lower_bound(nearFirst, nearLast, k,
                                [](const NearPatch& e, uint32_t at) { return e.position < at; });
    };
    // Patch j's light: a near patch's by its pieces, any other's patch-constant (E = π L F,
    // F analytic within analyticDistance patch diameters), seen along the ray to its
    // centroid (in a far cluster, as the whole cluster is).
    auto addPatch = [&](uint32_t j) {
        auto it = hasNear ? nearFrom(m_treePosition[j]) : nearLast;
        if (it != nearLast && it->patch == j) {
            if (request.part != Part::AllButNear) addNear(request, point.near, *it, sum);
            return;
        }
        const Rgb L = mirrorWeight * m_solution.reflectedLuminance(m_scene, m_mesh, j);
        if (L == Rgb(0.0)) return;
        const double within = m_scene.formFactors.analyticDistance;
        double f;
        if (real) {
            f = patchFormFactor(m_mesh, m_mesh.patches[j], x, n, within);
        } else {
            const ImagePatch p = imagePatch(m_mesh, m_mesh.patches[j], *image);
            f = patchFormFactor(p.corners, p.patch, x, n, within);
        }
        if (!(f > 0)) return;
        const Rgb e = L * (kPi * f);
        if (shared)
            sharedSum += e, sharedVisibility.addPatch(luminance(e), j);
        else
            rays.add(rayTarget(j), e);
    };
    // Where a source's samples fall (visibilityOffset): drawn per point, image, cluster
    // and node (`node` of the member tree; the whole cluster's shared rays take kWholeCluster).
    auto offset = [&](uint32_t node) { return visibilityOffset(x, m_sourceKeys[s], (uint64_t(c) << 24) + node); };
    // A far node's light times the share of its visibility samples seen (in a far
    // cluster, as the whole cluster is).
    auto addFar = [&](const FarSource& f, uint32_t node) {
        const Rgb e = farField(f, x, n, image);
        if (e == Rgb(0.0)) return;
        if (shared)
            sharedSum += e, sharedVisibility.addNode(luminance(e), f);
        else
            sum += e * visibleShare(
                           f, [&](uint32_t k) { return visiblePatch(C.patches[k]); }, point.raysFor(e), offset(node));
    };
    auto holdsNear = [&](const MemberNode& node) {
        auto it = nearFrom(node.begin);
        return it != nearLast && it->position < node.end;
    };
    // Depth first through the member tree: a node of `size` members farther than
    // farDiameters of its reach, holding no near patch, counts as one source. The root
    // first, from the contiguous copy (most clusters end there; reading each cluster's
    // own tree and far sources cost a cache miss each).
    auto isFar = [&](const FarSource& f, uint32_t size) {
        if (!(point.farDiameters > 0) || size <= 1) return false;
        const Vec3 at = real ? f.at : image->point(f.at);
        const double limit = point.farDiameters * f.reach;
        return glm::dot(at - x, at - x) > limit * limit;
    };
    const bool rootFar = !hasNear && isFar(m_rootFar[c], static_cast<uint32_t>(C.patches.size()));
    if (rootFar) addFar(m_rootFar[c], 0);
    const MemberTree& tree = m_trees[c];
    const std::vector<FarSource>& farSources = m_far[c];
    if (!rootFar)
        descend(tree, [&](uint32_t i, const MemberNode& node) {
            if (isFar(farSources[i], node.size()) && !holdsNear(node)) {
                addFar(farSources[i], i);
                return false;
            }
            if (!node.leaf()) return true;
            for (uint32_t k = node.begin; k < node.end; ++k) addPatch(C.patches[tree.order[k]]);
            return false;
        });
    rays.flush();
    if (shared && sharedSum != Rgb(0.0))
        sum += sharedSum * sharedVisibility.share(visiblePatch, point.raysFor(sharedSum), offset(kWholeCluster));
    return sum;
}

Rgb Gatherer::sumSources(const PointSources& point, const std::vector<uint32_t>& items) const {
    // Every item: source 0's clusters (or items), then (image, cluster) pairs image by
    // image: k = scene items + (image's place − 1) × clusters + c.
    const size_t clusters = m_clustering.clusters.size();
    const bool grouped = !items.empty();
    const size_t sceneCount = grouped ? items.size() : clusters;
    const size_t count = sceneCount + clusters * (point.sources.size() - 1);
    // Cluster c of image source s takes part unless no light passes its chain from c's
    // voxel to x, or no member of c faces its first mirror.
    auto open = [&](size_t s, size_t c) {
        return point.regionOpen[(s - 1) * point.regions + m_regions.regionOf[c]] && m_imageSends[s - 1][c];
    };
    auto sumOver = [&](size_t begin, size_t end, Rgb sum) {
        const size_t imageItems = begin > sceneCount ? begin - sceneCount : 0;
        size_t place = 1 + imageItems / clusters, c = imageItems % clusters;
        for (size_t k = begin; k != end; ++k) {
            if (k < sceneCount) {
                const uint32_t item = grouped ? items[k] : static_cast<uint32_t>(k);
                sum += item < clusters ? clusterContribution(point, 0, item)
                                       : groupContribution(point, static_cast<uint32_t>(item - clusters));
                continue;
            }
            const size_t s = point.sources[place];
            if (open(s, c)) sum += clusterContribution(point, s, c);
            if (++c == clusters) c = 0, ++place;
        }
        return sum;
    };
    if (point.request.threads == Threads::Serial) return sumOver(0, count, Rgb(0.0));
    // Deterministic for any thread count.
    return tbb::parallel_deterministic_reduce(
        tbb::blocked_range<size_t>(0, count, 16), Rgb(0.0),
        [&](const tbb::blocked_range<size_t>& r, Rgb sum) { return sumOver(r.begin(), r.end(), sum); },
        [](const Rgb& a, const Rgb& b) { return a + b; });
}

}  // namespace rayrad::radiosity
