#include <radiosity/clusters/cluster_tree.h>

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace rayrad::radiosity {

namespace {

/// Clusters whose normals differ by more than this in a component (about 20°) are split
/// by normal before position.
constexpr double kNormalSpread = 0.35;

/// Appends the group for order[begin, end) and, when it holds more than one cluster, its
/// two halves; returns its index.
uint32_t build(const Clustering& clustering, uint32_t begin, uint32_t end, ClusterTree& tree) {
    const auto index = static_cast<uint32_t>(tree.groups.size());
    tree.groups.emplace_back();
    ClusterGroup group;
    group.begin = begin, group.end = end;
    if (end - begin > 1) {
        const auto first = tree.order.begin() + begin, last = tree.order.begin() + end;
        // The box of a vector over the group's clusters: its low and high corners.
        auto box = [&](const Vec3 Cluster::*member) {
            Vec3 lo(1e300), hi(-1e300);
            for (auto c = first; c != last; ++c)
                lo = glm::min(lo, clustering.clusters[*c].*member), hi = glm::max(hi, clustering.clusters[*c].*member);
            return std::pair{lo, hi};
        };
        const auto middle = [&]() -> uint32_t {
            // Clusters facing different ways are parted first, at the middle of the widest
            // spread of a normal component: a group facing one way can be one source.
            const auto [low, high] = box(&Cluster::normal);
            const int normalAxis = longestAxis(high - low);
            if (high[normalAxis] - low[normalAxis] > kNormalSpread) {
                const double cut = 0.5 * (low[normalAxis] + high[normalAxis]);
                const auto split = std::partition(
                    first, last, [&](uint32_t c) { return clustering.clusters[c].normal[normalAxis] < cut; });
                return static_cast<uint32_t>(split - tree.order.begin());
            }
            // Then by position: at the median along the centroids' longest extent.
            const auto [lowest, highest] = box(&Cluster::centroid);
            const int axis = longestAxis(highest - lowest);
            const uint32_t median = begin + (end - begin) / 2;
            std::nth_element(first, tree.order.begin() + median, last, [&](uint32_t a, uint32_t b) {
                return clustering.clusters[a].centroid[axis] < clustering.clusters[b].centroid[axis];
            });
            return median;
        }();
        group.left = build(clustering, begin, middle, tree);
        group.right = build(clustering, middle, end, tree);
    }
    tree.groups[index] = group;
    return index;
}

/// The luminance vector Σ Y(L_j) A_j n_j of a far source (cd), from its channels' fluxes.
Vec3 fluxY(const FarSource& f) {
    return luminanceFlux(Vec3(f.flux[0]), Vec3(f.flux[1]), Vec3(f.flux[2]));
}

/// Angle (radians) between two unit directions.
double angleBetween(const Vec3& a, const Vec3& b) {
    return std::acos(std::clamp(glm::dot(a, b), -1.0, 1.0));
}

/// The group of two halves, from their far sources alone (no pass over the patches): the
/// moments moved to the joint centre of light by the parallel-axis rule,
///   M = Σ_h M_h + W_h (c_h − c)(c_h − c)ᵀ,  P = Σ_h P_h + (c_h − c) Φ_hᵀ
/// (W_h: a half's Σ Y(L_j) A_j, c_h its centre of light, Φ_h its luminance vector); the
/// reach and the normal cone bounded from the halves'; visibility sample i taken from the
/// half and the sample where the running power reaches (i + ½)/4 of it.
void mergeHalves(const ClusterGroup& a, const ClusterGroup& b, ClusterGroup& g) {
    FarSource& f = g.far;
    g.weight = a.weight + b.weight;
    const bool lit[2] = {a.weight > 0, b.weight > 0};
    f.mixed = a.far.mixed || b.far.mixed || (lit[0] && lit[1] && a.far.sign != b.far.sign);
    f.sign = lit[0] ? a.far.sign : b.far.sign;
    f.at = g.weight > 0 ? (a.weight * a.far.at + b.weight * b.far.at) / g.weight : 0.5 * (a.far.at + b.far.at);
    glm::dmat3 moment(0.0), turning(0.0);
    double radius = 0;
    Rgb power(0.0);
    for (const ClusterGroup* h : {&a, &b}) {
        const Vec3 d = h->far.at - f.at;
        moment += glm::dmat3(h->far.moment) + h->weight * glm::outerProduct(d, d);
        turning += glm::dmat3(h->far.turning) + glm::outerProduct(d, fluxY(h->far));
        radius = std::max(radius, glm::length(d) + 0.5 * h->far.reach);
        power += h->weight * Rgb(h->far.share);
    }
    for (int ch = 0; ch < 3; ++ch) f.flux[ch] = a.far.flux[ch] + b.far.flux[ch];
    f.moment = glm::mat3(moment);
    f.turning = glm::mat3(turning);
    f.reach = 2 * radius;
    f.share = glm::vec3(g.weight > 0 ? power / g.weight : Rgb(0.0));
    const Vec3 flux = fluxY(f);
    f.normal = glm::vec3(glm::length(flux) > 0 ? glm::normalize(flux) : Vec3(0.0));
    // Normal cone: a lit half's members lie within its own cone of its direction.
    double cone = 0;
    for (const ClusterGroup* h : {&a, &b})
        if (h->weight > 0) cone = std::max(cone, angleBetween(Vec3(f.normal), Vec3(h->far.normal)) + h->coneAngle);
    g.coneAngle = std::min(cone, kPi);
    for (uint32_t i = 0; i < 4; ++i) {
        const double target = (i + 0.5) / 4 * g.weight;
        const bool first = target < a.weight || !(b.weight > 0);
        const ClusterGroup& h = first ? a : b;
        const double within = first ? target : target - a.weight;
        const auto k = static_cast<uint32_t>(std::min(3.0, std::floor(4 * within / std::max(h.weight, 1e-300))));
        g.rayPatch[i] = h.rayPatch[k];
        f.rayTo[i] = i;
    }
}

}  // namespace

ClusterTree clusterTree(const PatchMesh& mesh, const Clustering& clustering, const std::vector<FarSource>& clusterFar,
                        const std::function<Rgb(uint32_t patch)>& luminanceOf) {
    ClusterTree tree;
    const auto count = static_cast<uint32_t>(clustering.clusters.size());
    tree.order.resize(count);
    for (uint32_t c = 0; c < count; ++c) tree.order[c] = c;
    if (count == 0) return tree;
    build(clustering, 0, count, tree);
    tree.position.resize(count);
    for (uint32_t k = 0; k < count; ++k) tree.position[tree.order[k]] = k;
    // Leaves: their cluster's own far source, its Σ Y(L_j) A_j and normal cone from its patches.
    tbb::parallel_for(size_t(0), tree.groups.size(), [&](size_t index) {
        ClusterGroup& g = tree.groups[index];
        if (!g.leaf()) return;
        const Cluster& C = clustering.clusters[tree.order[g.begin]];
        g.far = clusterFar[tree.order[g.begin]];
        g.weight = 0;
        double cosine = 1;
        for (uint32_t j : C.patches) {
            const Patch& p = mesh.patches[j];
            g.weight += std::abs(luminance(luminanceOf(j))) * p.area;
            cosine = std::min(cosine, glm::dot(p.normal, Vec3(g.far.normal)));
        }
        g.coneAngle = std::acos(std::clamp(cosine, -1.0, 1.0));
        for (uint32_t i = 0; i < 4; ++i) g.rayPatch[i] = C.patches[g.far.rayTo[i]];
    });
    // Groups: children follow their parent, so from the last group back every child is done.
    for (size_t index = tree.groups.size(); index-- > 0;) {
        ClusterGroup& g = tree.groups[index];
        if (!g.leaf()) mergeHalves(tree.groups[g.left], tree.groups[g.right], g);
    }
    return tree;
}

}  // namespace rayrad::radiosity
