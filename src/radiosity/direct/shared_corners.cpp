#include <radiosity/direct/shared_corners.h>

namespace rayrad::radiosity {

namespace {
/// Normals closer than this (1 − n₁·n₂) count as one plane.
constexpr double kSamePlane = 1e-10;
}  // namespace

std::vector<char> sharedCorners(const PatchMesh& mesh) {
    const size_t n = mesh.vertices.size();
    const std::vector<double> angleSum = vertexAngleSums(mesh);
    std::vector<Vec3> firstNormal(n, Vec3(0.0));
    std::vector<char> flat(n, 1);
    for (const Patch& p : mesh.patches)
        for (const uint32_t v : p.v) {
            if (firstNormal[v] == Vec3(0.0))
                firstNormal[v] = p.normal;
            else if (1 - glm::dot(firstNormal[v], p.normal) > kSamePlane)
                flat[v] = 0;
        }
    std::vector<char> shared(n, 0);
    for (uint32_t v = 0; v < n; ++v) {
        const auto through = mesh.outlinesThrough(v);
        const bool onOutline = through.first != through.second;
        const bool underSolid = !mesh.underSolid.empty() && mesh.underSolid[v];
        shared[v] = flat[v] && isInnerVertex(angleSum[v]) && !onOutline && !underSolid;
    }
    return shared;
}

}  // namespace rayrad::radiosity
