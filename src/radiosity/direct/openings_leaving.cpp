#include <radiosity/direct/openings_leaving.h>

#include <radiosity/mesh/patch_reflectance.h>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace rayrad::radiosity {

namespace {
constexpr int kLeavingSamples = 16;  ///< shadow rays from a patch's centroid to an opening
}

double leavingThroughOpenings(const scene::Scene& scene, const PatchMesh& mesh, const RadiositySolution& solution,
                              const DirectLight& lights, const Visibility& vis) {
    if (lights.openingCount() == 0 || solution.indirect.size() != mesh.patches.size()) return 0.0;
    // Per patch in order, then summed in order: deterministic.
    std::vector<double> left(mesh.patches.size(), 0.0);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, mesh.patches.size()), [&](const tbb::blocked_range<size_t>& r) {
        for (size_t i = r.begin(); i != r.end(); ++i) {
            const Patch& p = mesh.patches[i];
            const Rgb reflected = patchReflectance(scene, mesh, i) * (solution.directMean[i] + solution.indirect[i]);
            const double flux = luminance(reflected) * p.area;  // lm leaving the patch
            if (!(flux > 0)) continue;
            double f = 0;
            for (size_t k = 0; k < lights.openingCount(); ++k)
                f += lights.openingFormFactor(k, p.centroid, p.normal, vis, kLeavingSamples);
            left[i] = flux * f;
        }
    });
    double sum = 0;
    for (double l : left) sum += l;
    return sum;
}

}  // namespace rayrad::radiosity
