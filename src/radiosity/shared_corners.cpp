#include <radiosity/shared_corners.h>

#include <algorithm>
#include <cmath>

namespace rayrad::radiosity {

namespace {
/// Normals closer than this (1 − n₁·n₂) count as one plane; an angle sum within this
/// (rad) of 2π as a full fan.
constexpr double kSamePlane = 1e-10;
constexpr double kFullFan = 1e-6;
}  // namespace

std::vector<char> sharedCorners(const PatchMesh& mesh) {
    const size_t n = mesh.vertices.size();
    std::vector<double> angleSum(n, 0.0);  // rad: the patches' corner angles at each vertex
    std::vector<Vec3> firstNormal(n, Vec3(0.0));
    std::vector<char> flat(n, 1);
    for (const Patch& p : mesh.patches) {
        for (int k = 0; k < 3; ++k) {
            const uint32_t v = p.v[k];
            const Vec3 a = mesh.corner(p, (k + 1) % 3) - mesh.corner(p, k), b = mesh.corner(p, (k + 2) % 3) - mesh.corner(p, k);
            const double la = glm::length(a), lb = glm::length(b);
            if (la > 0 && lb > 0) angleSum[v] += std::acos(std::clamp(glm::dot(a, b) / (la * lb), -1.0, 1.0));
            if (firstNormal[v] == Vec3(0.0)) firstNormal[v] = p.normal;
            else if (1 - glm::dot(firstNormal[v], p.normal) > kSamePlane) flat[v] = 0;
        }
    }
    std::vector<char> shared(n, 0);
    for (uint32_t v = 0; v < n; ++v) {
        const auto through = mesh.outlinesThrough(v);
        const bool onOutline = through.first != through.second;
        const bool underSolid = !mesh.underSolid.empty() && mesh.underSolid[v];
        shared[v] = flat[v] && std::abs(angleSum[v] - 2 * kPi) < kFullFan && !onOutline && !underSolid;
    }
    return shared;
}

}  // namespace rayrad::radiosity
