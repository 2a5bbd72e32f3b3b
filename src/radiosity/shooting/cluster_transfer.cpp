#include <radiosity/shooting/cluster_transfer.h>

#include <radiosity/form_factors/form_factor.h>
#include <radiosity/form_factors/patch_transfer.h>

#include <algorithm>
#include <cmath>

namespace rayrad::radiosity {

namespace {
constexpr double kFarDiameters = 4.0;
/// Below this form factor one visibility ray instead of four (see the header).
constexpr double kOneRayFormFactor = 1e-3;

/// The point kernel g = cosθ_x cosθ_C / r² = (n·d)(−n_C·d) / r⁴ (1/m²) at x with unit
/// normal n from the source cluster's centroid, d = centroid − x.
double pointKernel(const Cluster& source, const Vec3& x, const Vec3& n) {
    const Vec3 d = source.centroid - x;
    const double r2 = glm::dot(d, d);
    if (r2 <= 0) return 0.0;
    return std::max(0.0, glm::dot(n, d)) * std::max(0.0, -glm::dot(source.normal, d)) / (r2 * r2);
}

/// What receiverShape divides the members' kernels by (1/m²): g at the receiver's
/// centroid with its mean normal. A receiver whose centroid lies (nearly) in the
/// source's plane, with members on both sides, has a g of rounding size there: dividing
/// by it gave ratios of 1e13 (a mirror image of a box face level with a wall's
/// centroid). Then the area-weighted mean of g over the members instead. Every member's
/// g is at most 1/r² ≤ 1/(r_centre − diameter/2)², and so is the mean: when g at the
/// centre is at least 1e-3 of that bound the mean need not be summed.
double shapeReference(const PatchMesh& mesh, const Cluster& source, const Cluster& receiver) {
    double atCentre = pointKernel(source, receiver.centroid, receiver.normal);
    if (atCentre <= 0) return 0.0;
    const double closest = glm::length(source.centroid - receiver.centroid) - 0.5 * receiver.diameter;
    if (closest > 0 && atCentre * closest * closest >= 1e-3) return atCentre;
    double mean = 0, area = 0;
    for (uint32_t j : receiver.patches) {
        const Patch& p = mesh.patches[j];
        mean += p.area * pointKernel(source, p.centroid, receiver.normal);
        area += p.area;
    }
    mean /= area;
    return atCentre < 1e-3 * mean ? mean : atCentre;
}

/// F at the receiver's centroid as its own surface sees the source (header): the member
/// sum at the receiver's distinct sample patches, their positions and normals, carried
/// to the centroid by the point kernel, F_c = g_ref Σ_s A_s F_s / Σ_s A_s g_s, so that
/// member k receives π L V g_k Σ A_s F_s / Σ A_s g_s. Samples the kernel does not reach
/// (g_s = 0) are left out of both sums. Returns a negative value when there is nothing
/// to calibrate with (g_ref = 0 or no sample with g_s > 0).
double sampledFormFactor(const PatchMesh& sourceMesh, const Cluster& source, const SourceGeometry* geometry,
                         const SourceLight* light, const PatchMesh& receiverMesh, const Cluster& receiver,
                         double analyticDistance) {
    const double reference = shapeReference(receiverMesh, source, receiver);
    if (reference <= 0) return -1.0;
    double sumF = 0, sumG = 0;
    for (int s = 0; s < 4; ++s) {
        bool repeat = false;
        for (int m = 0; m < s; ++m) repeat |= receiver.samples[m] == receiver.samples[s];
        if (repeat) continue;
        const Patch& p = receiverMesh.patches[receiver.samples[s]];
        const double g = pointKernel(source, p.centroid, p.normal);
        if (g <= 0) continue;
        sumF +=
            p.area * memberFormFactorSum(sourceMesh, source, geometry, light, p.centroid, p.normal, analyticDistance);
        sumG += p.area * g;
    }
    return sumG > 0 ? reference * sumF / sumG : -1.0;
}
}  // namespace

SourceGeometry sourceGeometry(const PatchMesh& mesh, const Cluster& source, const MemberTree& tree,
                              double farDiameters) {
    SourceGeometry g;
    if (farDiameters <= 0 || tree.nodes.size() < 2) return g;
    g.tree = &tree;
    g.farDiameters = farDiameters;
    g.unitFar =
        farSources(mesh, source, tree, std::vector<Rgb>(source.patches.size(), Rgb(1.0)), FarRayTargets::None);
    return g;
}

SourceLight sourceLight(const PatchMesh& mesh, const Cluster& source, const MemberTree& tree,
                        const std::vector<double>& luminance) {
    SourceLight out;
    double sum = 0, area = 0;
    for (size_t k = 0; k < source.patches.size(); ++k) {
        if (!(luminance[k] >= 0)) return out;
        const double a = mesh.patches[source.patches[k]].area;
        sum += luminance[k] * a, area += a;
    }
    if (!(sum > 0) || !(area > 0)) return out;
    const double mean = sum / area;
    out.member.resize(source.patches.size());
    for (size_t k = 0; k < source.patches.size(); ++k) out.member[k] = luminance[k] / mean;
    // Bottom-up (children follow their parent): a leaf sums its members, a node its two children.
    std::vector<double> weighted(tree.nodes.size(), 0.0), nodeArea(tree.nodes.size(), 0.0);
    for (size_t i = tree.nodes.size(); i-- > 0;) {
        const MemberNode& node = tree.nodes[i];
        if (node.leaf()) {
            for (uint32_t m = node.begin; m < node.end; ++m) {
                const uint32_t k = tree.order[m];
                const double a = mesh.patches[source.patches[k]].area;
                weighted[i] += out.member[k] * a, nodeArea[i] += a;
            }
        } else {
            weighted[i] = weighted[node.left] + weighted[node.right];
            nodeArea[i] = nodeArea[node.left] + nodeArea[node.right];
        }
    }
    out.node.resize(tree.nodes.size());
    for (size_t i = 0; i < tree.nodes.size(); ++i) out.node[i] = nodeArea[i] > 0 ? weighted[i] / nodeArea[i] : 1.0;
    return out;
}

double memberFormFactorSum(const PatchMesh& sourceMesh, const Cluster& source, const SourceGeometry* geometry,
                           const SourceLight* light, const Vec3& x, const Vec3& n, double analyticDistance) {
    if (light && light->member.empty()) light = nullptr;
    double f = 0;
    if (!geometry || !geometry->tree) {
        for (size_t k = 0; k < source.patches.size(); ++k)
            f += (light ? light->member[k] : 1.0) *
                 patchFormFactor(sourceMesh, sourceMesh.patches[source.patches[k]], x, n, analyticDistance);
        return f;
    }
    descend(*geometry->tree, [&](uint32_t index, const MemberNode& node) {
        const FarSource& far = geometry->unitFar[index];
        const double limit = geometry->farDiameters * far.reach;
        // Far, and wholly above or below x's horizon (the far field clips at its centre):
        // one source.
        if (node.size() > 1 && glm::dot(far.at - x, far.at - x) > limit * limit &&
            std::abs(glm::dot(n, far.at - x)) > 0.5 * far.reach) {
            f += (light ? light->node[index] : 1.0) * farField(far, x, n, nullptr)[1] / kPi;  // E = π L F at L = 1
            return false;
        }
        if (!node.leaf()) return true;
        for (uint32_t m = node.begin; m < node.end; ++m) {
            const uint32_t k = geometry->tree->order[m];
            f += (light ? light->member[k] : 1.0) *
                 patchFormFactor(sourceMesh, sourceMesh.patches[source.patches[k]], x, n, analyticDistance);
        }
        return false;
    });
    return f;
}

double clusterTransfer(const PatchMesh& sourceMesh, const Cluster& source, const ClusterSamples& sourceSamples,
                       const PatchMesh& receiverMesh, const Cluster& receiver, const Visibility& vis,
                       double analyticDistance, bool receiverDetail, const SourceGeometry* geometry,
                       const SourceLight* light, SplitTransfer* split) {
    if (split) *split = SplitTransfer{};
    Vec3 d = receiver.centroid - source.centroid;
    double r2 = glm::dot(d, d);
    double f = -1;
    if (r2 > kFarDiameters * kFarDiameters * source.diameter * source.diameter) {
        f = formFactorPointApprox(receiver.centroid, receiver.normal, source.centroid, source.normal,
                                  source.projectedArea);
    } else {
        if (receiverDetail && !receiver.planar)
            f = sampledFormFactor(sourceMesh, source, geometry, light, receiverMesh, receiver, analyticDistance);
        if (f < 0)
            f = memberFormFactorSum(sourceMesh, source, geometry, light, receiver.centroid, receiver.normal,
                                    analyticDistance);
    }
    if (f <= 0) return 0.0;
    // V from the sample pairs that face each other. On a curved cluster (a ball's cap) a
    // sample may face away from the other end: its ray runs through the ball itself and
    // voted "occluded" for light that only the members facing the source receive.
    bool faces[4], anyFacing = false;
    for (int k = 0; k < 4; ++k) {
        const Patch& at = receiverMesh.patches[receiver.samples[k]];
        const Vec3 u = sourceMesh.patches[sourceSamples[k]].centroid - at.centroid;
        faces[k] = glm::dot(at.normal, u) > 0 && glm::dot(sourceMesh.patches[sourceSamples[k]].normal, u) < 0;
        anyFacing |= faces[k];
    }
    int visible = 0, rays = 0;
    const int samples = f < kOneRayFormFactor ? 1 : 4;
    for (int k = 0; k < 4 && rays < samples; ++k) {
        // Skip repeated pairs (small clusters list the same member several times).
        bool repeat = false;
        for (int m = 0; m < k; ++m)
            repeat |= sourceSamples[m] == sourceSamples[k] && receiver.samples[m] == receiver.samples[k];
        if (repeat || (anyFacing && !faces[k])) continue;
        ++rays;
        const Patch& at = receiverMesh.patches[receiver.samples[k]];
        visible += vis.visibleFromSurface(at.centroid, at.normal, sourceMesh.patches[sourceSamples[k]].centroid);
    }
    if (split && visible > 0 && visible < rays) {
        split->partial = true;
        split->open = kPi * f;
    }
    return kPi * f * visible / rays;
}

/// Rays per receiving member in a split transfer (memberVisibility).
constexpr int kMemberRays = 2;

void memberVisibility(const PatchMesh& sourceMesh, const ClusterSamples& sourceSamples, const PatchMesh& receiverMesh,
                      const Cluster& receiver, const Visibility& vis, std::vector<double>& visible) {
    visible.assign(receiver.patches.size(), 0.0);
    for (size_t k = 0; k < receiver.patches.size(); ++k) {
        const Patch& at = receiverMesh.patches[receiver.patches[k]];
        // The source samples this member faces.
        uint32_t facing[4];
        int count = 0;
        for (uint32_t s : sourceSamples) {
            const Vec3 u = sourceMesh.patches[s].centroid - at.centroid;
            if (glm::dot(at.normal, u) > 0 && glm::dot(sourceMesh.patches[s].normal, u) < 0) facing[count++] = s;
        }
        if (count == 0) continue;  // faces no sample: the shape gives it (almost) nothing anyway
        const int rays = std::min(count, kMemberRays);
        int seen = 0;
        for (int m = 0; m < rays; ++m)
            seen +=
                vis.visibleFromSurface(at.centroid, at.normal, sourceMesh.patches[facing[(k + m) % count]].centroid);
        visible[k] = static_cast<double>(seen) / rays;
    }
}

/// How many members ahead receiverShape asks for a member's patch record.
constexpr size_t kShapePrefetch = 16;

void receiverShape(const PatchMesh& mesh, const Cluster& source, const Cluster& receiver, bool detail,
                   std::vector<double>& shape) {
    const size_t n = receiver.patches.size();
    shape.assign(n, 1.0);
    if (!detail || n == 1) return;
    const double reference = shapeReference(mesh, source, receiver);
    if (reference <= 0) return;  // the cluster-level transfer is 0 as well
    for (size_t k = 0; k < n; ++k) {
        // Every far receiver's members are read at every shot: at 1.2 M patches the records
        // (88 B each) do not stay in cache, and a load through the member list waited on
        // memory (58 % of this loop). Asking for a later member's record first hides it.
        if (k + kShapePrefetch < n) __builtin_prefetch(&mesh.patches[receiver.patches[k + kShapePrefetch]].centroid);
        const Patch& p = mesh.patches[receiver.patches[k]];
        shape[k] = pointKernel(source, p.centroid, p.normal) / reference;
    }
}

}  // namespace rayrad::radiosity
