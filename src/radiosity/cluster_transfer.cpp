#include <radiosity/cluster_transfer.h>

#include <radiosity/form_factor.h>
#include <radiosity/patch_transfer.h>

#include <algorithm>
#include <cmath>

namespace rayrad::radiosity {

namespace {
constexpr double kFarDiameters = 4.0;
/// Below this form factor one visibility ray instead of four (see the header).
constexpr double kOneRayFormFactor = 1e-3;
}

SourceGeometry sourceGeometry(const PatchMesh& mesh, const Cluster& source, const MemberTree& tree,
                              double farDiameters) {
    SourceGeometry g;
    if (farDiameters <= 0 || tree.nodes.size() < 2) return g;
    g.tree = &tree;
    g.farDiameters = farDiameters;
    g.unitFar = farSources(mesh, source, tree, std::vector<Rgb>(source.patches.size(), Rgb(1.0)));
    return g;
}

double memberFormFactorSum(const PatchMesh& sourceMesh, const Cluster& source, const SourceGeometry* geometry,
                           const Vec3& x, const Vec3& n, double analyticDistance) {
    double f = 0;
    if (!geometry || !geometry->tree) {
        for (uint32_t i : source.patches)
            f += patchFormFactor(sourceMesh, sourceMesh.patches[i], x, n, analyticDistance);
        return f;
    }
    descend(*geometry->tree, [&](uint32_t index, const MemberNode& node) {
        const FarSource& far = geometry->unitFar[index];
        const double limit = geometry->farDiameters * far.reach;
        // Far, and wholly above or below x's horizon (the far field clips at its centre):
        // one source.
        if (node.size() > 1 && glm::dot(far.at - x, far.at - x) > limit * limit &&
            std::abs(glm::dot(n, far.at - x)) > 0.5 * far.reach) {
            f += farField(far, x, n, nullptr)[1] / kPi;  // E = π L F at L = 1
            return false;
        }
        if (!node.leaf()) return true;
        for (uint32_t m = node.begin; m < node.end; ++m) {
            const Patch& p = sourceMesh.patches[source.patches[geometry->tree->order[m]]];
            f += patchFormFactor(sourceMesh, p, x, n, analyticDistance);
        }
        return false;
    });
    return f;
}

double clusterTransfer(const PatchMesh& sourceMesh, const Cluster& source, const ClusterSamples& sourceSamples,
                       const PatchMesh& receiverMesh, const Cluster& receiver, const Visibility& vis,
                       double analyticDistance, const SourceGeometry* geometry) {
    Vec3 d = receiver.centroid - source.centroid;
    double r2 = glm::dot(d, d);
    double f = 0;
    if (r2 > kFarDiameters * kFarDiameters * source.diameter * source.diameter) {
        f = formFactorPointApprox(receiver.centroid, receiver.normal, source.centroid, source.normal,
                                  source.projectedArea);
    } else {
        f = memberFormFactorSum(sourceMesh, source, geometry, receiver.centroid, receiver.normal, analyticDistance);
    }
    if (f <= 0) return 0.0;
    int visible = 0, rays = 0;
    const int samples = f < kOneRayFormFactor ? 1 : 4;
    for (int k = 0; k < samples; ++k) {
        // Skip repeated pairs (small clusters list the same member several times).
        bool repeat = false;
        for (int m = 0; m < k; ++m) repeat |= sourceSamples[m] == sourceSamples[k] && receiver.samples[m] == receiver.samples[k];
        if (repeat) continue;
        ++rays;
        const Patch& at = receiverMesh.patches[receiver.samples[k]];
        visible += vis.visibleFromSurface(at.centroid, at.normal, sourceMesh.patches[sourceSamples[k]].centroid);
    }
    return kPi * f * visible / rays;
}

void receiverShape(const PatchMesh& mesh, const Cluster& source, const Cluster& receiver, bool detail,
                   std::vector<double>& shape) {
    const size_t n = receiver.patches.size();
    shape.assign(n, 1.0);
    if (!detail || n == 1) return;
    // Point kernel cosθ_x cosθ_C / r² = (n·d)(−n_C·d) / r⁴ from the source cluster's
    // centroid, d = centroid − x.
    auto kernel = [&](const Vec3& x, const Vec3& normal) {
        Vec3 d = source.centroid - x;
        double r2 = glm::dot(d, d);
        if (r2 <= 0) return 0.0;
        return std::max(0.0, glm::dot(normal, d)) * std::max(0.0, -glm::dot(source.normal, d)) / (r2 * r2);
    };
    double atCentre = kernel(receiver.centroid, receiver.normal);
    if (atCentre <= 0) return;  // the cluster-level transfer is 0 as well
    // A receiver whose centroid lies (nearly) in the source's plane, with members on
    // both sides, has a kernel of rounding size at the centre: dividing by it gave
    // ratios of 1e13 (a mirror image of a box face level with a wall's centroid). Then
    // normalise by the area-weighted mean over the members instead.
    // Every member's kernel is at most 1/r² ≤ 1/(r_centre − diameter/2)², and so is the
    // mean: when atCentre is at least 1e-3 of that bound the mean need not be summed.
    const double closest = glm::length(source.centroid - receiver.centroid) - 0.5 * receiver.diameter;
    if (!(closest > 0 && atCentre * closest * closest >= 1e-3)) {
        double mean = 0, area = 0;
        for (uint32_t j : receiver.patches) {
            const Patch& p = mesh.patches[j];
            mean += p.area * kernel(p.centroid, receiver.normal);
            area += p.area;
        }
        mean /= area;
        if (atCentre < 1e-3 * mean) atCentre = mean;
    }
    for (size_t k = 0; k < n; ++k) {
        const Patch& p = mesh.patches[receiver.patches[k]];
        shape[k] = kernel(p.centroid, p.normal) / atCentre;
    }
}

}  // namespace rayrad::radiosity
