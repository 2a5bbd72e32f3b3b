#include <radiosity/clusters/far_field.h>

#include <radiosity/form_factors/form_factor.h>

#include <algorithm>
#include <cmath>

namespace rayrad::radiosity {

namespace {

FarSource farSource(const PatchMesh& mesh, const Cluster& C, const MemberTree& tree, const MemberNode& node,
                    const std::vector<Rgb>& luminance, FarRayTargets targets) {
    FarSource f;
    bool positive = false, negative = false;
    for (uint32_t k = node.begin; k < node.end; ++k) {
        const double y = rayrad::luminance(luminance[tree.order[k]]);
        positive |= y > 0, negative |= y < 0;
    }
    f.mixed = positive && negative;
    f.sign = negative ? -1.0 : 1.0;
    // Luminance-weighted centroid: the far field's first-order term vanishes there.
    double weight = 0;
    Vec3 at(0.0);
    Rgb power(0.0);
    std::array<Vec3, 3> flux{};  // summed in double, kept in float
    glm::dmat3 moment(0.0), turning(0.0);
    for (uint32_t k = node.begin; k < node.end; ++k) {
        const uint32_t m = tree.order[k];
        const Patch& p = mesh.patches[C.patches[m]];
        const Rgb pj = double(f.sign) * luminance[m] * p.area;  // cd
        const double y = rayrad::luminance(pj);
        for (int ch = 0; ch < 3; ++ch) flux[ch] += pj[ch] * p.normal;
        power += pj;
        weight += y;
        at += y * p.centroid;
    }
    f.at = weight > 0 ? at / weight : node.centroid;
    // Visibility samples stratified by power: sample i where the running sum reaches (i + ½)/4 of it.
    if (targets == FarRayTargets::PowerSamples) {
        double sum = 0;
        uint32_t k = node.begin;
        for (int i = 0; i < 4; ++i) {
            const double target = (i + 0.5) / 4 * weight;
            for (; k + 1 < node.end; ++k) {
                const uint32_t m = tree.order[k];
                const double y = double(f.sign) * rayrad::luminance(luminance[m]) * mesh.patches[C.patches[m]].area;
                if (sum + y >= target) break;
                sum += y;
            }
            f.rayTo[i] = tree.order[k];
        }
    }
    f.share = glm::vec3(weight > 0 ? power / weight : Rgb(0.0));
    double r = 0;
    for (uint32_t k = node.begin; k < node.end; ++k) {
        const uint32_t m = tree.order[k];
        const Patch& p = mesh.patches[C.patches[m]];
        const Vec3 v0 = mesh.corner(p, 0), v1 = mesh.corner(p, 1), v2 = mesh.corner(p, 2);
        for (const Vec3& v : {v0, v1, v2}) r = std::max(r, glm::length(v - f.at));
        const double y = double(f.sign) * rayrad::luminance(luminance[m]) * p.area;  // cd
        moment += y * triangleSecondMoment(v0, v1, v2, f.at);  // ∫ (y − at)(y − at)ᵀ dA, weighted
        turning += y * glm::outerProduct(p.centroid - f.at, p.normal);
    }
    f.reach = 2 * r;
    f.moment = glm::mat3(moment);
    f.turning = glm::mat3(turning);
    for (int ch = 0; ch < 3; ++ch) f.flux[ch] = glm::vec3(flux[ch]);
    const Vec3 fluxY = luminanceFlux(flux[0], flux[1], flux[2]);
    f.normal = glm::vec3(glm::length(fluxY) > 0 ? glm::normalize(fluxY) : Vec3(0.0));
    return f;
}

}  // namespace

Vec3 luminanceFlux(const Vec3& red, const Vec3& green, const Vec3& blue) {
    return Vec3(rayrad::luminance(Rgb(red.x, green.x, blue.x)), rayrad::luminance(Rgb(red.y, green.y, blue.y)),
                rayrad::luminance(Rgb(red.z, green.z, blue.z)));
}

std::vector<FarSource> farSources(const PatchMesh& mesh, const Cluster& cluster, const MemberTree& tree,
                                  const std::vector<Rgb>& luminance, FarRayTargets targets) {
    std::vector<FarSource> out(tree.nodes.size());
    for (size_t i = 0; i < tree.nodes.size(); ++i)
        out[i] = farSource(mesh, cluster, tree, tree.nodes[i], luminance, targets);
    return out;
}

Rgb farField(const FarSource& f, const Vec3& x, const Vec3& n, const MirrorImage* image) {
    // In an image: the centroid mirrored, Φ and m turned by R, M' = R M Rᵀ, times Π Ks.
    auto turn = [image](const Vec3& v) { return image ? image->direction(v) : v; };
    const Vec3 u = (image ? image->point(f.at) : f.at) - x;
    const double s = glm::dot(u, u);  // r²
    const double a = glm::dot(n, u);  // r cosθ_x
    if (a <= 0) return Rgb(0.0);
    const Vec3 m = turn(Vec3(f.normal));
    const double b = -glm::dot(m, u);  // r cosθ_y
    // The expansion is of g(u) = a b / s², which is smooth but not clamped: a node that
    // faces away (b ≤ 0) gives nothing, whatever its second-order term says.
    if (b <= 0) return Rgb(0.0);
    // ½ tr(H M), H the Hessian of g (form_factor.h).
    const glm::dmat3 R = image ? glm::dmat3(image->transform) : glm::dmat3(1.0);
    const glm::dmat3 moment(f.moment);
    const glm::dmat3 M = image ? R * moment * glm::transpose(R) : moment;
    const double trHM = pointKernelHessianTrace(u, n, m, M);
    // −tr(J P), J = ∂[(n·u) u / s²]/∂u = (u nᵀ + a I)/s² − 4 a u uᵀ/s³ (P mirrored as M is).
    const glm::dmat3 turning(f.turning);
    const glm::dmat3 P = image ? R * turning * glm::transpose(R) : turning;
    const double trJP =
        (glm::dot(n, P * u) + a * (P[0][0] + P[1][1] + P[2][2])) / (s * s) - 4 * a * glm::dot(u, P * u) / (s * s * s);
    const Rgb weight = image ? image->weight : Rgb(1.0);
    Rgb e(0.0);
    for (int ch = 0; ch < 3; ++ch) {
        const double zeroth = a * std::max(0.0, -glm::dot(turn(Vec3(f.flux[ch])), u)) / (s * s);  // cosθ_x (−Φ·u) / r³
        e[ch] = double(f.sign) * weight[ch] * std::max(0.0, zeroth + double(f.share[ch]) * (0.5 * trHM - trJP));
    }
    return e;
}

}  // namespace rayrad::radiosity
