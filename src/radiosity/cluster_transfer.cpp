#include <radiosity/cluster_transfer.h>

#include <radiosity/form_factor.h>
#include <radiosity/patch_transfer.h>

#include <algorithm>
#include <cmath>

namespace rayrad::radiosity {

namespace {
constexpr double kFarDiameters = 4.0;
}

double clusterTransfer(const PatchMesh& mesh, const Cluster& source, const Cluster& receiver, const Visibility& vis,
                       double analyticDistance) {
    Vec3 d = receiver.centroid - source.centroid;
    double r2 = glm::dot(d, d);
    double f = 0;
    if (r2 > kFarDiameters * kFarDiameters * source.diameter * source.diameter) {
        f = formFactorPointApprox(receiver.centroid, receiver.normal, source.centroid, source.normal, source.area);
    } else {
        for (uint32_t i : source.patches)
            f += patchFormFactor(mesh, mesh.patches[i], receiver.centroid, receiver.normal, analyticDistance);
    }
    if (f <= 0) return 0.0;
    int visible = 0, rays = 0;
    for (int k = 0; k < 4; ++k) {
        // Skip repeated pairs (small clusters list the same member several times).
        bool repeat = false;
        for (int m = 0; m < k; ++m) repeat |= source.samples[m] == source.samples[k] && receiver.samples[m] == receiver.samples[k];
        if (repeat) continue;
        ++rays;
        visible += vis.visible(mesh.patches[source.samples[k]].centroid, mesh.patches[receiver.samples[k]].centroid);
    }
    return kPi * f * visible / rays;
}

void receiverShape(const PatchMesh& mesh, const Cluster& source, const Cluster& receiver, bool detail,
                   std::vector<double>& shape) {
    const size_t n = receiver.patches.size();
    shape.assign(n, 1.0);
    if (!detail || n == 1) return;
    double weighted = 0;
    for (size_t k = 0; k < n; ++k) {
        const Patch& p = mesh.patches[receiver.patches[k]];
        Vec3 d = source.centroid - p.centroid;
        double r2 = glm::dot(d, d);
        double r = std::sqrt(r2);
        double kernel = r2 > 0 ? std::max(0.0, glm::dot(p.normal, d) / r) *
                                     std::max(0.0, -glm::dot(source.normal, d) / r) / r2
                               : 0.0;
        shape[k] = kernel;
        weighted += kernel * p.area;
    }
    if (weighted <= 0) {
        shape.assign(n, 1.0);
        return;
    }
    double scale = receiver.area / weighted;  // area-weighted mean 1
    for (double& v : shape) v *= scale;
}

}  // namespace rayrad::radiosity
