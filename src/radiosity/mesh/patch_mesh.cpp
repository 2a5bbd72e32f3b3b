#include <radiosity/mesh/patch_mesh.h>

#include <fmt/format.h>

#include <algorithm>

namespace rayrad::radiosity {

double PatchMesh::totalArea() const {
    double a = 0;
    for (const auto& p : patches) a += p.area;
    return a;
}

std::vector<std::vector<uint32_t>> patchesAround(const PatchMesh& mesh) {
    std::vector<std::vector<uint32_t>> around(mesh.vertices.size());
    for (uint32_t i = 0; i < mesh.patches.size(); ++i)
        for (uint32_t v : mesh.patches[i].v) around[v].push_back(i);
    return around;
}

std::vector<double> vertexAngleSums(const PatchMesh& mesh) {
    std::vector<double> sum(mesh.vertices.size(), 0.0);
    for (const Patch& p : mesh.patches)
        for (int k = 0; k < 3; ++k) {
            const Vec3 a = mesh.corner(p, (k + 1) % 3) - mesh.corner(p, k),
                       b = mesh.corner(p, (k + 2) % 3) - mesh.corner(p, k);
            const double la = glm::length(a), lb = glm::length(b);
            if (la > 0 && lb > 0) sum[p.v[k]] += std::acos(std::clamp(glm::dot(a, b) / (la * lb), -1.0, 1.0));
        }
    return sum;
}

bool isInnerVertex(double angleSum) {
    return std::abs(angleSum - 2 * kPi) < 1e-6;
}

void computeGeometry(const PatchMesh& mesh, Patch& p) {
    computeGeometry({mesh.vertices[p.v[0]], mesh.vertices[p.v[1]], mesh.vertices[p.v[2]]}, p);
}

void computeGeometry(const std::array<Vec3, 3>& corners, Patch& p) {
    const Vec3 &a = corners[0], &b = corners[1], &c = corners[2];
    Vec3 n = glm::cross(b - a, c - a);
    double len = glm::length(n);
    p.area = 0.5 * len;
    p.normal = len > 0 ? n / len : Vec3(0.0);
    p.centroid = (a + b + c) / 3.0;
    p.diameter = std::max({glm::length(b - a), glm::length(c - b), glm::length(a - c)});
}

std::string toString(const Patch& p) {
    return fmt::format("Patch{{v=[{},{},{}], area={:.6g} m², normal={}, material={}}}", p.v[0], p.v[1], p.v[2], p.area,
                       rayrad::toString(p.normal), p.material);
}

void forPatchesNear(const PatchMesh& mesh, const Visibility* spatial, const Vec3& x, double radius,
                    const std::function<void(uint32_t)>& visit) {
    if (spatial && spatial->patchesNear(x, radius, visit)) return;
    for (size_t i = 0; i < mesh.patches.size(); ++i) visit(static_cast<uint32_t>(i));
}

}  // namespace rayrad::radiosity
