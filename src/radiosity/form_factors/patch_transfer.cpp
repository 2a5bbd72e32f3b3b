#include <radiosity/form_factors/patch_transfer.h>

#include <radiosity/form_factors/form_factor.h>

namespace rayrad::radiosity {

double patchFormFactor(const PatchMesh& mesh, const Patch& source, const Vec3& x, const Vec3& n,
                       double analyticDistance) {
    return patchFormFactor({mesh.corner(source, 0), mesh.corner(source, 1), mesh.corner(source, 2)}, source, x, n,
                           analyticDistance);
}

double patchFormFactor(const std::array<Vec3, 3>& corners, const Patch& source, const Vec3& x, const Vec3& n,
                       double analyticDistance) {
    Vec3 d = source.centroid - x;
    double r2 = glm::dot(d, d);
    double near = analyticDistance * source.diameter;
    if (r2 < near * near) return formFactorToPolygon(x, n, corners.data(), 3, source.normal);
    return formFactorPointApprox(x, n, source.centroid, source.normal, source.area);
}

}  // namespace rayrad::radiosity
