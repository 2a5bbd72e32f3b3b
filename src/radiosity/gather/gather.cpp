#include <radiosity/gather/gather.h>
#include <radiosity/clusters/image_clusters.h>
#include <radiosity/mesh/patch_reflectance.h>

#include <core/ray_batch.h>
#include <radiosity/form_factors/form_factor.h>
#include <radiosity/form_factors/patch_transfer.h>
#include <radiosity/gather/visibility_share.h>

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>  // parallel_deterministic_reduce: same sum for any thread count

#include <algorithm>
#include <cmath>
#include <vector>

namespace rayrad::radiosity {

namespace {
/// A source patch is "near" x within this many diameters of its centroid.
constexpr double kNearDiameters = 2.0;
/// A far source whose light at the point is below this share of the indirect illuminance
/// expected there takes one visibility ray, any other four (see gatherWith).
constexpr double kWeakSourceShare = 1e-3;
/// A cluster farther than this many of its diameters shares its visibility rays.
constexpr double kClusterVisibilityDiameters = 2.0;
/// Near patches holding at least 1/kRefineShares of the near field's ρ F are refined to
/// the full tolerance; smaller ones to a tolerance looser in proportion.
constexpr double kRefineShares = 20;
/// A re-gather of small weight counts nodes as far from this many of their diameters at
/// the least (see gatherWith).
constexpr double kLeastFarDiameters = 2.0;
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
    : m_scene(scene), m_mesh(mesh), m_clustering(clustering), m_solution(solution), m_vis(vis), m_options(options),
      m_nudge(1e-6 * scene.diagonal()) {
    m_treePosition.resize(mesh.patches.size());
    for (const auto& C : clustering.clusters) {
        double size = 0;
        for (uint32_t j : C.patches) size = std::max(size, mesh.patches[j].diameter);
        m_clusterPatchSize.push_back(size);
        MemberTree tree = memberTree(mesh, C, kFarLeafSize);
        for (uint32_t i = 0; i < tree.order.size(); ++i) m_treePosition[C.patches[tree.order[i]]] = i;
        std::vector<Rgb> luminance(C.patches.size());
        for (size_t k = 0; k < C.patches.size(); ++k) luminance[k] = solution.reflectedLuminance(scene, mesh, C.patches[k]);
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
    if (level < 0) return solutionCorner(patch, corner);
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
    auto [idAt, added] = memo.m_midpointIds.emplace(std::make_pair(std::min(a, b), std::max(a, b)),
                                                    firstId + memo.m_midpointIds.size());
    const uint64_t id = idAt->second;
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
    if (level <= 0) return gatherWith(x, n, nullptr, true, nullptr, weight, Part::All, expected);
    // The memo is filled while the near list is built (serially); the sum runs in parallel.
    CornerSource corners = [&](size_t patch, int corner, double share) {
        return cornerIndirect(patch, corner, level - 1, classOf(weight * share), memo);
    };
    if (level <= m_options.gatherLevels - m_options.gatherRefineLevels)
        return gatherWith(x, n, &corners, true, nullptr, weight, Part::All, expected);
    MidpointSource midpoints = [&](size_t patch, uint64_t a, uint64_t b, const Vec3& y, double share) {
        return midpointIndirect(patch, a, b, y, level - 1, classOf(weight * share), memo);
    };
    return gatherWith(x, n, &corners, true, &midpoints, weight, Part::All, expected);
}

Rgb Gatherer::gatherWith(const Vec3& x, const Vec3& n, const CornerSource* cornerIndirectOf, bool parallel,
                         const MidpointSource* midpoints, double weight, Part part, double expected,
                         const std::vector<uint32_t>* nearSet) const {
    // Near patches get linear luminance from corner values (refined toward x with
    // gathered midpoints when asked), the rest a patch-constant one.
    struct Near {
        uint32_t patch;
        uint32_t position;  ///< in its cluster's member tree order
        uint32_t first, count;  ///< its pieces in `pieces`
        double F;  ///< the whole patch's form factor seen from x
        /// The form factor of `piece`, when it is the whole patch, else −1 (not known).
        double known(const NearPiece& piece) const { return count == 1 && piece.depth == 0 ? F : -1; }
    };
    std::vector<Near> near;
    std::vector<NearPiece> pieces;  ///< every near patch's pieces, one run each (one allocation, not one per patch)
    // Adds near patch e's light at x to `into`, piece by piece.
    auto addNear = [&](const Near& e, Rgb& into) {
        for (uint32_t k = e.first; k < e.first + e.count; ++k) {
            const NearPiece& piece = pieces[k];
            into += integrateLinear(x, n, piece.p.data(), piece.L.data(), m_mesh.patches[e.patch].normal, piece.depth,
                                    e.known(piece));
        }
    };
    /// The clusters holding near patches, in increasing order, and their range in `near`
    /// (sorted by tree position: a node's near patches are a contiguous run).
    struct NearCluster {
        uint32_t cluster;
        size_t begin, end;
    };
    std::vector<NearCluster> nearClusters;
    if (cornerIndirectOf) {
        // The near patches that face x, in cluster order.
        struct Candidate {
            uint32_t cluster, patch;
            double share;  ///< ρ F: how much of an error in its corner values reaches x
            double F;
        };
        std::vector<Candidate> candidates;
        // Near to x, or the set asked for (in cluster order either way).
        const std::vector<uint32_t> nearX = nearSet ? std::vector<uint32_t>() : nearPatches({x, x});
        for (uint32_t j : nearSet ? *nearSet : nearX) {
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
            if (nearClusters.empty() || nearClusters.back().cluster != e.cluster)
                nearClusters.push_back({e.cluster, near.size(), near.size()});
            near.push_back({j, m_treePosition[j], 0, 0, e.F});
            nearClusters.back().end = near.size();
            if (part == Part::AllButNear) continue;  // which patches are near is all it needs
            const Patch& p = m_mesh.patches[j];
            const Rgb rho = patchReflectance(m_scene, m_mesh, j);
            const bool sliver = 2 * p.area < m_options.minRefineWidth * p.diameter;
            const bool detailed = e.share >= detailFrom;
            std::array<RefinePoint, 3> corners;
            for (int k = 0; k < 3; ++k) {
                const Rgb E(m_solution.directCorner[3 * j + k]);
                const Rgb indirect = detailed ? (*cornerIndirectOf)(j, k, e.share) : solutionCorner(j, k);
                corners[k] = {m_mesh.corner(p, k), p.v[k], rho * (E + indirect) / kPi, E};
            }
            // A piece is refined while its midpoints depart from linear by more than the
            // tolerance; patches holding less than 1/kRefineShares of the near field's share
            // may depart more, in proportion (400 slivers of a sofa do not each need it), and
            // so may a gather whose error reaches the sensor with weight w < 1, by 1/w.
            const double tolerance = m_options.gatherRefineTolerance *
                                     std::max(1.0, shareSum / (kRefineShares * e.share)) /
                                     (m_options.gatherMinWeight > 0 ? weight : 1.0);
            const size_t first = pieces.size();
            refineNear(x, j, corners, 0, detailed && !sliver ? midpoints : nullptr, e.share, tolerance, pieces);
            near.back().first = static_cast<uint32_t>(first);
            near.back().count = static_cast<uint32_t>(pieces.size() - first);
        }
        for (const NearCluster& c : nearClusters)
            std::sort(near.begin() + static_cast<std::ptrdiff_t>(c.begin), near.begin() + static_cast<std::ptrdiff_t>(c.end),
                      [](const Near& a, const Near& b) { return a.position < b.position; });
    }
    if (part == Part::Near) {
        Rgb sum(0.0);
        for (const Near& e : near) addNear(e, sum);
        return sum;
    }

    // A far node's error falls as (reach / r)³ (its expansion is of second order); an error
    // in a gather of weight w reaches the sensor times w, so nodes may count as far from
    // farDiameters · ∛w (never nearer than kLeastFarDiameters): the same error at the sensor.
    const double farDiameters = m_options.gatherFarDiameters > 0 && weight < 1
                                    ? std::max(kLeastFarDiameters, m_options.gatherFarDiameters * std::cbrt(weight))
                                    : m_options.gatherFarDiameters;
    // Sum over clusters: near patches by sub-triangles, other patches with their own rays
    // when close, far clusters with shared rays (form factors still per member; the
    // visibility sampled where their light comes from: ClusterVisibility), and far
    // member-tree nodes as one source each (see the constructor's comment).
    // Source s = 0 is the real scene, s = i + 1 its image i in the mirrors.
    // Per mirror image, which voxels' clusters may send x light through its chain (most do
    // not: a cluster there adds nothing, so skipping it leaves every sum as it was).
    // A far source's visibility: up to four rays, or one in a re-gather (weight < 1),
    // whose error reaches the sensor diminished.
    // When x is expected to receive `expected` lx (> 0; the caller's estimate), a source
    // bringing less than kWeakSourceShare of that takes one ray too (the error its
    // visibility can bring is at most its light, and one ray's is unbiased), and any
    // other four (unbiased, where two that agree would miss a small hidden part).
    const double weakBelow = kWeakSourceShare * expected;
    auto raysFor = [&](const Rgb& e) {
        if (weight < 1) return VisibilityRays::One;
        if (!(expected > 0)) return VisibilityRays::UpToFour;
        return luminance(e) < weakBelow ? VisibilityRays::One : VisibilityRays::Four;
    };
    const size_t regions = m_regions.regions.size();
    std::vector<char> regionOpen(m_mirrorViews.size() * regions);  // not thread_local: a waiting thread may run another gather
    std::vector<uint32_t> sources{0};  // the scene itself, then the images x faces
    for (size_t i = 0; i < m_mirrorViews.size(); ++i) {
        const MirrorImage& image = m_mirrorViews[i]->image;
        // Nothing comes through a chain whose last mirror x does not face.
        if (!m_scene.mirrors[image.chain.back()].facedBy(x, n)) continue;
        sources.push_back(static_cast<uint32_t>(i + 1));
        for (size_t r = 0; r < regions; ++r) {
            const VoxelRegions::Region& region = m_regions.regions[r];
            regionOpen[i * regions + r] = image.mayPassToPoint(image.point(region.centre), region.radius, x);
        }
    }
    // Cluster c of source s takes part unless s is an image whose chain no light passes
    // from c's voxel to x, or whose first mirror no member of c faces.
    auto open = [&](size_t s, size_t c) {
        return s == 0 || (regionOpen[(s - 1) * regions + m_regions.regionOf[c]] && m_imageSends[s - 1][c]);
    };
    auto contribution = [&](size_t s, size_t c) {
        const bool real = s == 0;
        const MirrorImage* image = real ? nullptr : &m_mirrorViews[s - 1]->image;
        const Cluster& C = m_clustering.clusters[c];  // members mirrored as they are used
        const Visibility& vis = real ? m_vis : *m_mirrorViews[s - 1]->path;
        const Rgb mirrorWeight = real ? Rgb(1.0) : image->weight;  // Π Ks of the chain
        auto nearOf = std::lower_bound(nearClusters.begin(), nearClusters.end(), c,
                                       [](const NearCluster& e, size_t k) { return e.cluster < k; });
        const bool hasNear = real && nearOf != nearClusters.end() && nearOf->cluster == c;
        const auto nearFirst = hasNear ? near.begin() + static_cast<std::ptrdiff_t>(nearOf->begin) : near.end();
        const auto nearLast = hasNear ? near.begin() + static_cast<std::ptrdiff_t>(nearOf->end) : near.end();
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
        // Patch j's contribution e (lx), seen along the ray to its centroid (in a far
        // cluster, as the whole cluster is).
        auto add = [&](const Rgb& e, uint32_t j) {
            if (shared) {
                sharedSum += e, sharedVisibility.addPatch(luminance(e), j);
                return;
            }
            rays.add(rayTarget(j), e);
        };
        // The first near patch at or after tree position k.
        auto nearFrom = [&](uint32_t k) {
            return std::lower_bound(nearFirst, nearLast, k, [](const Near& e, uint32_t at) { return e.position < at; });
        };
        // F from patch j in this source: analytic within analyticDistance patch diameters,
        // the point approximation beyond.
        auto formFactor = [&](uint32_t j) {
            const double within = m_scene.formFactors.analyticDistance;
            if (real) return patchFormFactor(m_mesh, m_mesh.patches[j], x, n, within);
            const ImagePatch p = imagePatch(m_mesh, m_mesh.patches[j], *image);
            return patchFormFactor(p.corners, p.patch, x, n, within);
        };
        auto addPatch = [&](uint32_t j) {
            auto it = hasNear ? nearFrom(m_treePosition[j]) : nearLast;
            if (it != nearLast && it->patch == j) {
                if (part == Part::AllButNear) return;
                addNear(*it, sum);
                return;
            }
            const Rgb L = mirrorWeight * m_solution.reflectedLuminance(m_scene, m_mesh, j);
            if (L == Rgb(0.0)) return;
            const double f = formFactor(j);
            if (f > 0) add(L * (kPi * f), j);  // E = π L F
        };
        // Where a source's samples fall (visibilityOffset): drawn per point, image, cluster
        // and node (`node` of the member tree; the whole cluster's shared rays take kCluster).
        constexpr uint32_t kCluster = (1u << 24) - 1;
        auto offset = [&](uint32_t node) { return visibilityOffset(x, m_sourceKeys[s], (uint64_t(c) << 24) + node); };
        // A far node's light times the share of its visibility samples seen (in a far
        // cluster, as the whole cluster is).
        auto addFar = [&](const FarSource& f, uint32_t node) {
            const Rgb e = farField(f, x, n, image);
            if (e == Rgb(0.0)) return;
            if (shared) sharedSum += e, sharedVisibility.addNode(luminance(e), f);
            else
                sum += e * visibleShare(f, [&](uint32_t k) { return visiblePatch(C.patches[k]); }, raysFor(e),
                                        offset(node));
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
            if (!(farDiameters > 0) || size <= 1) return false;
            const Vec3 at = real ? f.at : image->point(f.at);
            const double limit = farDiameters * f.reach;
            return glm::dot(at - x, at - x) > limit * limit;
        };
        const bool rootFar = !hasNear && isFar(m_rootFar[c], static_cast<uint32_t>(C.patches.size()));
        if (rootFar) addFar(m_rootFar[c], 0);
        const MemberTree& tree = m_trees[c];
        const std::vector<FarSource>& farSources = m_far[c];
        if (!rootFar) descend(tree, [&](uint32_t i, const MemberNode& node) {
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
            sum += sharedSum * sharedVisibility.share(visiblePatch, raysFor(sharedSum), offset(kCluster));
        return sum;
    };
    // The scene's own clusters: in a re-gather (weight < 1), groups of clusters far from x
    // (ClusterTree), holding no near patch, count as one source each, seen through two
    // visibility rays, four where they disagree; item clusters + g stands for group g. In the sensor's own gather,
    // every cluster on its own.
    const size_t clusters = m_clustering.clusters.size();
    std::vector<uint32_t> sceneItems;
    if (weight < 1 && farDiameters > 0 && !m_clusterTree.groups.empty()) {
        std::vector<uint32_t> nearAt;  // tree positions of the clusters holding near patches
        for (const NearCluster& c : nearClusters) nearAt.push_back(m_clusterTree.position[c.cluster]);
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
                sceneItems.push_back(m_clusterTree.order[g.begin]);
                continue;
            }
            const double limit = farDiameters * g.far.reach;
            if (!g.far.mixed && g.coneAngle <= m_groupCone && glm::dot(g.far.at - x, g.far.at - x) > limit * limit && !holdsNear(g)) {
                sceneItems.push_back(static_cast<uint32_t>(clusters + index));
                continue;
            }
            stack.push_back(g.right), stack.push_back(g.left);
        }
    }
    const bool grouped = !sceneItems.empty();
    // A far group's light times the share of its visibility samples seen.
    auto groupContribution = [&](uint32_t index) {
        const ClusterGroup& g = m_clusterTree.groups[index];
        const Rgb e = farField(g.far, x, n, nullptr);
        if (e == Rgb(0.0)) return e;
        auto seen = [&](uint32_t i) { return m_vis.visibleFromSurface(x, n, m_mesh.patches[g.rayPatch[i]].centroid); };
        return e * visibleShare(g.far, seen, VisibilityRays::UpToFour, visibilityOffset(x, 0, (uint64_t(1) << 63) | index));
    };
    // Every item: source 0's clusters (or items), then (image, cluster) pairs image by
    // image: k = scene items + (image's place − 1) × clusters + c.
    const size_t sceneCount = grouped ? sceneItems.size() : clusters;
    const size_t count = sceneCount + clusters * (sources.size() - 1);
    auto sumOver = [&](size_t begin, size_t end, Rgb sum) {
        const size_t imageItems = begin > sceneCount ? begin - sceneCount : 0;
        size_t place = 1 + imageItems / clusters, c = imageItems % clusters;
        for (size_t k = begin; k != end; ++k) {
            if (k < sceneCount) {
                const uint32_t item = grouped ? sceneItems[k] : static_cast<uint32_t>(k);
                sum += item < clusters ? contribution(0, item) : groupContribution(static_cast<uint32_t>(item - clusters));
                continue;
            }
            if (open(sources[place], c)) sum += contribution(sources[place], c);
            if (++c == clusters) c = 0, ++place;
        }
        return sum;
    };
    if (!parallel) return sumOver(0, count, Rgb(0.0));
    // Deterministic for any thread count.
    return tbb::parallel_deterministic_reduce(
        tbb::blocked_range<size_t>(0, count, 16), Rgb(0.0),
        [&](const tbb::blocked_range<size_t>& r, Rgb sum) { return sumOver(r.begin(), r.end(), sum); },
        [](const Rgb& a, const Rgb& b) { return a + b; });
}

}  // namespace rayrad::radiosity
