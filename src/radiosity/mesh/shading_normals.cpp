#include <radiosity/mesh/shading_normals.h>

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace rayrad::radiosity {

void computeShadingNormals(PatchMesh& mesh, double smoothingAngleDeg) {
    mesh.cornerNormal.clear();
    if (!(smoothingAngleDeg > 0)) return;
    const double cosCrease = std::cos(smoothingAngleDeg * kPi / 180);
    // The patches around each vertex (compressed rows).
    std::vector<uint32_t> start(mesh.vertices.size() + 1, 0);
    for (const auto& p : mesh.patches)
        for (uint32_t v : p.v) ++start[v + 1];
    for (size_t v = 0; v < mesh.vertices.size(); ++v) start[v + 1] += start[v];
    std::vector<uint32_t> around(start.back()), fill(start.begin(), start.end() - 1);
    for (uint32_t i = 0; i < mesh.patches.size(); ++i)
        for (uint32_t v : mesh.patches[i].v) around[fill[v]++] = i;

    std::vector<glm::vec3> normals(3 * mesh.patches.size());
    std::vector<char> bent(mesh.patches.size(), 0);
    tbb::parallel_for(size_t(0), mesh.patches.size(), [&](size_t i) {
        const Patch& p = mesh.patches[i];
        for (int k = 0; k < 3; ++k) {
            Vec3 sum(0.0);
            for (uint32_t a = start[p.v[k]]; a < start[p.v[k] + 1]; ++a) {
                const Patch& q = mesh.patches[around[a]];
                if (glm::dot(q.normal, p.normal) >= cosCrease) sum += q.area * q.normal;
            }
            const double length = glm::length(sum);
            const Vec3 n = length > 0 ? sum / length : p.normal;
            normals[3 * i + k] = glm::vec3(n);
            if (glm::dot(n, p.normal) < 1 - 1e-9) bent[i] = 1;
        }
    });
    for (char b : bent)
        if (b) {
            mesh.cornerNormal = std::move(normals);
            return;
        }
}

Vec3 shadingNormal(const PatchMesh& mesh, size_t i, double u, double v) {
    const Patch& p = mesh.patches[i];
    if (mesh.cornerNormal.empty()) return p.normal;
    const Vec3 n = (1 - u - v) * Vec3(mesh.cornerNormal[3 * i]) + u * Vec3(mesh.cornerNormal[3 * i + 1]) +
                   v * Vec3(mesh.cornerNormal[3 * i + 2]);
    const double length = glm::length(n);
    return length > 1e-6 && glm::dot(n, p.normal) > 0 ? n / length : p.normal;
}

Vec3 shadingPoint(const PatchMesh& mesh, size_t i, double u, double v) {
    const Patch& p = mesh.patches[i];
    const Vec3 x = mesh.pointAt(p, u, v);
    if (mesh.cornerNormal.empty()) return x;
    const double b[3] = {1 - u - v, u, v};
    Vec3 lifted(0.0);
    for (int k = 0; k < 3; ++k) {
        const Vec3& corner = mesh.corner(p, k);
        const Vec3 n = Vec3(mesh.cornerNormal[3 * i + k]);
        Vec3 t = x - corner;
        const double below = std::min(0.0, glm::dot(t, n));
        t -= below * n;  // onto the corner's tangent plane, if x lies below it
        lifted += b[k] * (corner + t);
    }
    return lifted;
}

}  // namespace rayrad::radiosity
