#include <raytrace/ray_tracer.h>

#include <radiosity/radiosity.h>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <optional>

namespace rayrad::raytrace {

namespace {

/// Fresnel reflectance of unpolarised light at a dielectric boundary; cosI > 0 on the
/// incident side, eta = n_incident / n_transmitted. 1 for total internal reflection;
/// `cosT` gets the transmitted angle's cosine.
double fresnelDielectric(double cosI, double eta, double& cosT) {
    double sin2T = eta * eta * std::max(0.0, 1 - cosI * cosI);
    if (sin2T >= 1) return 1.0;
    cosT = std::sqrt(1 - sin2T);
    double rs = (eta * cosI - cosT) / (eta * cosI + cosT);
    double rp = (cosI - eta * cosT) / (cosI + eta * cosT);
    return 0.5 * (rs * rs + rp * rp);
}

/// What a ray that leaves the scene sees: the sky, the ground below the horizon and the
/// sun's disk (cd/m²), or black without daylight.
Rgb outdoors(const scene::Scene& scene, const Vec3& unit) {
    if (!scene.daylight) return Rgb(0.0);
    const scene::Daylight& d = *scene.daylight;
    return Rgb(d.luminance(unit) + (d.inSunDisk(unit) ? d.sunDiskLuminance() : 0.0));
}

Rgb shadeHit(const scene::Scene& scene, const radiosity::PatchMesh& mesh, const radiosity::RadiositySolution& solution,
             const radiosity::DirectLight& lights, const EmbreeScene& embree, const Vec3& origin, const Vec3& dir,
             Hit h, int areaLightSamples, Random& rng, const RayCone& cone, int depth, const HitGather* gather,
             radiosity::PixelLightMemo* pixel);

}  // namespace

Hit seenSide(const radiosity::PatchMesh& mesh, const EmbreeScene& embree, const Vec3& origin, const Vec3& dir,
             const Hit& h) {
    if (!h.found || h.specular || glm::dot(mesh.patches[h.patch].normal, dir) < 0) return h;
    const double window = 4 * embree.epsilon() / glm::length(dir);
    const Hit front = embree.intersect(origin, dir, h.t - window, h.t + window, /*frontOnly=*/true);
    return front.found && !front.specular ? front : Hit{};
}

Rgb shadeRay(const scene::Scene& scene, const radiosity::PatchMesh& mesh, const radiosity::RadiositySolution& solution,
             const radiosity::DirectLight& lights, const EmbreeScene& embree, const Vec3& origin, const Vec3& dir,
             int areaLightSamples, Random& rng, const RayCone& cone, int depth, const HitGather* gather,
             radiosity::PixelLightMemo* pixel) {
    const Hit h = embree.intersect(origin, dir, 0.0, std::numeric_limits<double>::infinity());
    const Vec3 unit = glm::normalize(dir);
    // The glazing of the openings the ray passes through on its way (1 without daylight).
    const double glazing =
        scene.daylight ? lights.openingTransmittance(
                             origin, unit, h.found ? h.t * glm::length(dir) : std::numeric_limits<double>::infinity())
                       : 1.0;
    if (!h.found) return glazing * outdoors(scene, unit);
    return glazing * shadeHit(scene, mesh, solution, lights, embree, origin, dir, h, areaLightSamples, rng, cone, depth,
                              gather, pixel);
}

namespace {

Rgb shadeHit(const scene::Scene& scene, const radiosity::PatchMesh& mesh, const radiosity::RadiositySolution& solution,
             const radiosity::DirectLight& lights, const EmbreeScene& embree, const Vec3& origin, const Vec3& dir,
             Hit h, int areaLightSamples, Random& rng, const RayCone& cone, int depth, const HitGather* gather,
             radiosity::PixelLightMemo* pixel) {
    const Vec3 unit = glm::normalize(dir);
    const RayCone onward = cone.continuedAt(h.t * glm::length(dir));  // the footprint at the hit
    if (h.specular) {
        // Whitted recursion: mirrors reflect (front side only), glass reflects and refracts.
        const SpecularTriangle& t = embree.specular(h.patch);
        const scene::Material& m = scene.materials[t.material];
        if (depth >= scene.render.maxDepth) return Rgb(0.0);
        Vec3 x = origin + h.t * dir;
        const double offset = embree.epsilon();
        double cosI = -glm::dot(unit, t.normal);
        Vec3 reflected = unit + 2.0 * cosI * t.normal;
        if (m.kind == scene::SurfaceKind::Mirror) {
            if (cosI <= 0) return Rgb(0.0);  // the back of a mirror is black
            return m.specular * shadeRay(scene, mesh, solution, lights, embree, x + offset * t.normal, reflected,
                                         areaLightSamples, rng, onward, depth + 1, gather);
        }
        // Glass: entering from the front (cosI > 0) or leaving through the back.
        bool entering = cosI > 0;
        Vec3 n = entering ? t.normal : -t.normal;  // faces the incoming ray
        double c = std::abs(cosI);
        double eta = entering ? 1.0 / m.ior : m.ior;
        double cosT = 0;
        double R = fresnelDielectric(c, eta, cosT);
        Rgb L = R * shadeRay(scene, mesh, solution, lights, embree, x + offset * n, reflected, areaLightSamples, rng,
                             onward, depth + 1, gather);
        if (R < 1) {
            Vec3 refracted = eta * unit + (eta * c - cosT) * n;  // Snell's law
            L += (1 - R) * shadeRay(scene, mesh, solution, lights, embree, x - offset * n, refracted, areaLightSamples,
                                    rng, onward, depth + 1, gather);
        }
        return L;
    }
    h = seenSide(mesh, embree, origin, dir, h);
    if (!h.found) return Rgb(0.0);  // the back of a one-sided surface
    const radiosity::Patch& p = mesh.patches[h.patch];
    const scene::Material& m = scene.materials[p.material];
    Rgb L = m.emission;
    if (m.reflectance == Rgb(0.0)) return L;
    // ρ at the hit: the texture filtered over the sample's footprint here (its mean over
    // the patch is what the radiosity used).
    std::pair<Vec3, Vec3> footprint{Vec3(0.0), Vec3(0.0)};
    if (m.texture >= 0) footprint = surfaceFootprint(onward.width, unit, p.normal);
    const Rgb rho = radiosity::reflectanceAt(scene, mesh, h.patch, h.u, h.v, footprint.first, footprint.second);
    // With virtual lights; the weakest real lights shadow-tested only while they matter. The
    // hit point is recomputed in double from the barycentrics (more precise than o + t d);
    // on curved meshes it is lifted toward the smooth surface and shaded with the
    // interpolated normal, so the facets do not show.
    const Vec3 x = radiosity::shadingPoint(mesh, h.patch, h.u, h.v);
    const Vec3 n = radiosity::shadingNormal(mesh, h.patch, h.u, h.v);
    Rgb indirect(0.0);
    if (gather) {
        indirect = gather->gatherer.indirectAt(mesh.pointAt(p, h.u, h.v), p.normal, gather->memo);  // on its own plane
    } else if (!solution.vertexIndirect.empty()) {
        indirect = radiosity::interpolateIndirect(mesh, solution, h.patch, h.u, h.v);
    }
    // The untested lights' error is bounded relative to all the hit receives, indirect too.
    const Rgb direct = lights.illuminanceForDisplay(x, n, embree, areaLightSamples, &rng, scene.render.directThreshold,
                                                    std::max(0.0, luminance(indirect)), depth == 0 ? pixel : nullptr,
                                                    static_cast<int64_t>(h.patch));
    return L + rho * (direct + indirect) / kPi;  // L = ρ E / π
}

}  // namespace

double compressionLuminance(const scene::Scene& scene, const radiosity::PatchMesh& mesh,
                            const radiosity::RadiositySolution& solution) {
    double sumLog = 0, area = 0;
    for (size_t i = 0; i < mesh.patches.size() && i < solution.directMean.size(); ++i) {
        const double L = luminance(solution.reflectedLuminance(scene, mesh, i));
        if (!(L > 0) || !std::isfinite(L)) continue;
        sumLog += std::log(L) * mesh.patches[i].area;
        area += mesh.patches[i].area;
    }
    return area > 0 ? std::exp(sumLog / area) / 0.18 : 0.0;
}

HdrImage render(const scene::Scene& scene, const radiosity::PatchMesh& mesh,
                const radiosity::RadiositySolution& solution, const radiosity::DirectLight& lights,
                const EmbreeScene& embree, const ImageCamera& camera, const scene::RenderOptions& options,
                const std::function<void(double)>& onProgress, DisplayAverage* display, int rowBegin, int rowEnd,
                const radiosity::Gatherer* gatherer) {
    HdrImage image(camera.width(), camera.height());
    const double Lc = display ? display->compressionLuminance : 0.0;
    if (display) display->image = HdrImage(camera.width(), camera.height());
    const int spp = options.samplesPerPixel;
    const int strata = std::max(1, static_cast<int>(std::floor(std::sqrt(static_cast<double>(spp)))));
    // area_light_samples is a pixel's budget of shadow rays per area light: its samples
    // share it (⌈n / spp⌉ each), so a pixel averages about n rays per light at any spp.
    const int raysPerHit = std::max(1, (options.areaLightSamples + spp - 1) / spp);
    // A sample's footprint: its stratum of the pixel (textures are filtered over it, and the
    // samples average the strata).
    const RayCone pixel = camera.pixelCone();
    const RayCone sampleCone{pixel.width / strata, pixel.spread / strata};
    std::atomic<int> rowsDone{0};
    const int first = std::clamp(rowBegin, 0, image.height),
              last = rowEnd < 0 ? image.height : std::clamp(rowEnd, first, image.height);
    tbb::parallel_for(tbb::blocked_range<int>(first, last, 1), [&](const tbb::blocked_range<int>& rows) {
        for (int y = rows.begin(); y != rows.end(); ++y) {
            radiosity::GatherMemo memo;  // the row's re-gathered corners (render.indirect "gather")
            std::optional<HitGather> gather;
            if (gatherer) gather.emplace(HitGather{*gatherer, memo});
            radiosity::PixelLightMemo pixelLights;  // emptied at each pixel (its vectors keep their capacity)
            for (int x = 0; x < image.width; ++x) {
                Random rng(options.seed, static_cast<uint64_t>(y) * image.width + x);
                pixelLights.patch = -1;
                Rgb sum(0.0), weighted(0.0);
                double weights = 0;
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
                    const CameraRay r = camera.ray(x + jx, y + jy);
                    const Rgb sample = r.valid ? shadeRay(scene, mesh, solution, lights, embree, r.origin, r.direction,
                                                          raysPerHit, rng, sampleCone, 0, gather ? &*gather : nullptr,
                                                          options.shareFarShadows ? &pixelLights : nullptr)
                                               : Rgb(0.0);
                    sum += sample;
                    if (Lc > 0) {
                        const double w = 1 / (1 + std::max(0.0, luminance(sample)) / Lc);
                        weighted += w * sample;
                        weights += w;
                    }
                }
                image.at(x, y) = sum / static_cast<double>(spp);
                if (display) display->image.at(x, y) = Lc > 0 && weights > 0 ? weighted / weights : image.at(x, y);
            }
            int done = ++rowsDone;
            if (onProgress) onProgress(static_cast<double>(done) / std::max(1, last - first));
        }
    });
    return image;
}

}  // namespace rayrad::raytrace
