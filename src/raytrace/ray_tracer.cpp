#include <raytrace/ray_tracer.h>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <atomic>
#include <cmath>
#include <limits>

namespace rayrad::raytrace {

Rgb shadeRay(const scene::Scene& scene, const radiosity::PatchMesh& mesh, const radiosity::RadiositySolution& solution,
             const radiosity::DirectLight& lights, const EmbreeScene& embree, const Vec3& origin, const Vec3& dir,
             int areaLightSamples, Random& rng) {
    Hit h = embree.intersect(origin, dir, 0.0, std::numeric_limits<double>::infinity());
    if (!h.found) return Rgb(0.0);
    const radiosity::Patch& p = mesh.patches[h.patch];
    if (glm::dot(p.normal, dir) >= 0) return Rgb(0.0);  // back face: surfaces are one-sided
    const scene::Material& m = scene.materials[p.material];
    // Recompute the hit point in double from the barycentrics (more precise than o + t d).
    Vec3 x = mesh.pointAt(p, h.u, h.v);
    Rgb L = m.emission;
    if (m.reflectance == Rgb(0.0)) return L;
    Rgb direct = lights.illuminance(x, p.normal, embree, areaLightSamples, &rng);
    Rgb indirect = solution.vertexIndirect.empty()
                       ? Rgb(0.0)
                       : radiosity::interpolateIndirect(mesh, solution, h.patch, h.u, h.v);
    return L + m.reflectance * (direct + indirect) / kPi;  // L = ρ E / π
}

HdrImage render(const scene::Scene& scene, const radiosity::PatchMesh& mesh, const radiosity::RadiositySolution& solution,
                const radiosity::DirectLight& lights, const EmbreeScene& embree, const PinholeCamera& camera,
                const scene::RenderOptions& options, const std::function<void(double)>& onProgress) {
    HdrImage image(camera.width(), camera.height());
    const int spp = options.samplesPerPixel;
    const int strata = std::max(1, static_cast<int>(std::floor(std::sqrt(static_cast<double>(spp)))));
    std::atomic<int> rowsDone{0};
    tbb::parallel_for(tbb::blocked_range<int>(0, image.height, 1), [&](const tbb::blocked_range<int>& rows) {
        for (int y = rows.begin(); y != rows.end(); ++y) {
            for (int x = 0; x < image.width; ++x) {
                Random rng(options.seed, static_cast<uint64_t>(y) * image.width + x);
                Rgb sum(0.0);
                for (int s = 0; s < spp; ++s) {
                    // Stratified jitter for the first strata² samples, uniform for the rest.
                    double jx, jy;
                    if (s < strata * strata) {
                        jx = (s % strata + rng.nextDouble()) / strata;
                        jy = (s / strata + rng.nextDouble()) / strata;
                    } else {
                        jx = rng.nextDouble();
                        jy = rng.nextDouble();
                    }
                    Vec3 dir = camera.direction(x + jx, y + jy);
                    sum += shadeRay(scene, mesh, solution, lights, embree, camera.position(), dir,
                                    options.areaLightSamples, rng);
                }
                image.at(x, y) = sum / static_cast<double>(spp);
            }
            int done = ++rowsDone;
            if (onProgress) onProgress(static_cast<double>(done) / image.height);
        }
    });
    return image;
}

}  // namespace rayrad::raytrace
