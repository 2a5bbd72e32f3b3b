#include <radiosity/direct/openings_leaving.h>

#include <radiosity/mesh/patch_reflectance.h>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace rayrad::radiosity {

namespace {
constexpr int kLeavingSamples = 16;  ///< shadow rays from a patch's centroid to an opening
constexpr int kSkyRays = 4;          ///< kSkyRays² rays from a patch's centroid toward the open sky
}

double leavingThroughOpenings(const scene::Scene& scene, const PatchMesh& mesh, const RadiositySolution& solution,
                              const DirectLight& lights, const Visibility& vis) {
    if (lights.openingCount() == 0 || solution.indirect.size() != mesh.patches.size()) return 0.0;
    // Per patch in order, then summed in order: deterministic.
    std::vector<double> left(mesh.patches.size(), 0.0);
    const double far = 4 * std::max(scene.diagonal(), 1.0);  // m: beyond the scene from anywhere in it
    tbb::parallel_for(tbb::blocked_range<size_t>(0, mesh.patches.size()), [&](const tbb::blocked_range<size_t>& r) {
        for (size_t i = r.begin(); i != r.end(); ++i) {
            const Patch& p = mesh.patches[i];
            const Rgb reflected = patchReflectance(scene, mesh, i) * (solution.directMean[i] + solution.indirect[i]);
            const double flux = luminance(reflected) * p.area;  // lm leaving the patch
            if (!(flux > 0)) continue;
            double f = 0;
            for (size_t k = 0; k < lights.openingCount(); ++k)
                f += lights.openingFormFactor(k, p.centroid, p.normal, vis, kLeavingSamples);
            // And into the open from outdoor surfaces: stratified cosine-distributed rays
            // that meet nothing and pass through no opening.
            const auto [t1, t2] = tangentFrame(p.normal);
            int open = 0;
            for (int a = 0; a < kSkyRays; ++a)
                for (int b = 0; b < kSkyRays; ++b) {
                    const double u = (a + 0.5) / kSkyRays, phi = 2 * kPi * (b + 0.5) / kSkyRays;
                    const double radius = std::sqrt(u);
                    const Vec3 w = radius * std::cos(phi) * t1 + radius * std::sin(phi) * t2 + std::sqrt(1 - u) * p.normal;
                    if (lights.openingsCrossed(p.centroid, w, far) == 0 &&
                        vis.visibleFromSurface(p.centroid, p.normal, p.centroid + far * w))
                        ++open;
                }
            left[i] = flux * (f + static_cast<double>(open) / (kSkyRays * kSkyRays));
        }
    });
    double sum = 0;
    for (double l : left) sum += l;
    return sum;
}

}  // namespace rayrad::radiosity
