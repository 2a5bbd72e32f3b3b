#include <radiosity/direct_pass.h>

#include <tbb/parallel_for.h>

namespace rayrad::radiosity {

void computeDirect(const PatchMesh& mesh, const DirectLight& lights, const Visibility& vis, int areaSamples,
                   RadiositySolution& solution) {
    solution.directMean.assign(mesh.patches.size(), Rgb(0.0));
    solution.directCorner.assign(3 * mesh.patches.size(), Rgb(0.0));
    tbb::parallel_for(size_t(0), mesh.patches.size(), [&](size_t i) {
        const Patch& p = mesh.patches[i];
        Rgb centre = lights.illuminance(p.centroid, p.normal, vis, areaSamples, nullptr);
        Rgb corners(0.0);
        for (int k = 0; k < 3; ++k) {
            Vec3 x = mesh.corner(p, k) + 1e-4 * (p.centroid - mesh.corner(p, k));
            Rgb e = lights.illuminance(x, p.normal, vis, areaSamples, nullptr);
            solution.directCorner[3 * i + k] = e;
            corners += e;
        }
        solution.directMean[i] = 0.75 * centre + corners / 12.0;
    });
}

}  // namespace rayrad::radiosity
