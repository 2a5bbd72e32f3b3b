#include <radiosity/mesh/covered_patches.h>

#include <tbb/parallel_for.h>

namespace rayrad::radiosity {

bool coveredAt(const Visibility& vis, const Vec3& x, const Vec3& n, double reach, double lift) {
    return !vis.visible(x + lift * n, x + (lift + reach) * n);
}

std::vector<char> coveredPatches(const PatchMesh& mesh, const Visibility& vis, double lift) {
    std::vector<char> covered(mesh.patches.size(), 0);
    tbb::parallel_for(size_t(0), mesh.patches.size(), [&](size_t i) {
        const Patch& p = mesh.patches[i];
        covered[i] = coveredAt(vis, p.centroid, p.normal, kCoverDiameters * p.diameter, lift);
    });
    return covered;
}

}  // namespace rayrad::radiosity
