#include <raytrace/view_samples.h>

#include <core/random.h>
#include <raytrace/camera.h>
#include <raytrace/ray_tracer.h>

#include <limits>

namespace rayrad::raytrace {

std::vector<ViewSample> viewSamples(const scene::Scene& scene, const scene::Camera& camera,
                                    const radiosity::PatchMesh& mesh, const EmbreeScene& embree, int count,
                                    uint64_t seed, int& missed) {
    std::vector<ViewSample> samples;
    missed = 0;
    const ImageCamera image(camera);
    Random rng(seed);
    const double far = std::numeric_limits<double>::infinity();
    for (int k = 0; k < count; ++k) {
        const double px = rng.nextDouble() * image.width(), py = rng.nextDouble() * image.height();
        const CameraRay ray = image.ray(px, py);
        const Hit h = ray.valid ? seenSide(mesh, embree, ray.origin, ray.direction,
                                           embree.intersect(ray.origin, ray.direction, 0.0, far))
                                : Hit{};
        const scene::Material* m = h.found && !h.specular ? &scene.materials[mesh.patches[h.patch].material] : nullptr;
        if (!m || luminance(m->reflectance) <= 0 || luminance(m->emission) > 0) {
            ++missed;
            continue;
        }
        const radiosity::Patch& p = mesh.patches[h.patch];
        samples.push_back({h.patch, mesh.pointAt(p, h.u, h.v), p.normal});
    }
    return samples;
}

}  // namespace rayrad::raytrace
