#include <radiosity/direct/direct_light.h>

#include <core/check.h>
#include <core/ray_batch.h>
#include <radiosity/form_factors/form_factor.h>
#include <scene/daylight/glazing.h>
#include <scene/polygon.h>

#include <algorithm>
#include <cmath>
#include <functional>

namespace rayrad::radiosity {

namespace {
/// An area light within this many of its diameters gets all its shadow rays; farther, it
/// subtends a smaller solid angle and its penumbrae are narrower, and the rays fall in
/// proportion to the solid angle (at least one).
constexpr double kAllSamplesDiameters = 5.0;
/// Beyond this many of its diameters an area light's form factor is the second-order one.
constexpr double kFarFormFactorDiameters = 5.0;
}  // namespace

AreaLight makeAreaLight(std::vector<Vec3> vertices, const Vec3& normal, const Rgb& luminance) {
    AreaLight light;
    light.vertices = std::move(vertices);
    light.normal = normal;
    light.area = scene::polygonArea(light.vertices);
    light.luminance = luminance;
    for (const auto& v : light.vertices) light.centre += v;
    light.centre /= static_cast<double>(light.vertices.size());
    for (const auto& v : light.vertices) light.radius = std::max(light.radius, glm::length(v - light.centre));
    for (const auto& t : scene::triangulate(light.vertices)) {
        std::array<Vec3, 3> tri{light.vertices[t[0]], light.vertices[t[1]], light.vertices[t[2]]};
        light.triangles.push_back(tri);
        light.triangleAreas.push_back(0.5 * glm::length(glm::cross(tri[1] - tri[0], tri[2] - tri[0])));
    }
    light.moments = polygonMoments(light.triangles);
    return light;
}

double areaLightFormFactor(const AreaLight& light, const Vec3& x, const Vec3& n) {
    const Vec3 d = light.centre - x;
    const double far = kFarFormFactorDiameters * 2 * light.radius;  // m
    bool farAndAbove = glm::dot(d, d) > far * far;
    for (size_t k = 0; k < light.vertices.size() && farAndAbove; ++k)
        farAndAbove = glm::dot(n, light.vertices[k] - x) > 0;
    if (farAndAbove) return formFactorSecondOrder(x, n, light.moments, light.normal, light.area);
    return formFactorToPolygon(x, n, light.vertices.data(), static_cast<int>(light.vertices.size()), light.normal);
}

DirectLight::DirectLight(const scene::Scene& scene) : m_pointLights(scene.lights) {
    m_beyondScene = 4 * std::max(scene.diagonal(), 1.0);
    if (scene.daylight) m_daylight = std::make_shared<const scene::Daylight>(*scene.daylight);
    for (const auto& g : scene.groups) {
        const auto& mat = scene.materials[g.material];
        const bool opening = mat.isOpening() && m_daylight;
        if (!mat.isEmissive() && !opening) continue;
        for (const auto& poly : g.polygons) {
            std::vector<Vec3> vertices;
            for (uint32_t i : poly) vertices.push_back(g.positions[i]);
            const Vec3 normal = scene::polygonNormal(vertices);
            if (!opening) {
                m_areaLights.push_back(makeAreaLight(std::move(vertices), normal, mat.emission));
                continue;
            }
            // An opening: the sky behind it, seen from its front; its mean luminance
            // Φ_in / (π A) from what the unobstructed sky and ground send in.
            const double mean = enteringIlluminance(*m_daylight, normal, mat.transmittance) / kPi;
            // A dark sky behind it: no light of its own, but the sun still comes through it.
            if (!(mean > 0) && !m_daylight->hasDirectSun()) continue;
            AreaLight light = makeAreaLight(std::move(vertices), normal, Rgb(mean));
            light.sky = m_daylight.get();
            light.transmittance = mat.transmittance;
            m_anyGlazing |= mat.transmittance < 1;
            m_openings.push_back(m_areaLights.size());
            m_areaLights.push_back(std::move(light));
        }
    }
    if (m_daylight && m_daylight->hasDirectSun()) {
        // The sun: a point source so far away (10⁵ scene diagonals) that its direction and
        // its 1/d² change by at most 2·10⁻⁵ across the scene; I = E_n d².
        scene::PointLight sun;
        const double d = 1e5 * std::max(scene.diagonal(), 1.0);
        sun.position = 0.5 * (scene.boundsMin + scene.boundsMax) + d * m_daylight->sunDirection;
        sun.intensity = Rgb(m_daylight->sunNormalIlluminance * d * d);
        sun.where = m_daylight->where + "/sun";
        m_sun = static_cast<int>(m_pointLights.size());
        m_pointLights.push_back(sun);
    }
    m_mirrors = scene.mirrors;
    for (const auto& m : m_mirrors) m_convexMirrors &= scene::isConvexAround(m.polygon, m.normal);
    m_images = mirrorImagesFor(scene);
    for (const auto& image : m_images) {
        std::vector<AreaLight> mirrored;
        for (const auto& a : m_areaLights) {
            AreaLight v = a;
            // An odd number of reflections reverses the winding: reverse it back.
            for (auto& p : v.vertices) p = image.point(p);
            if (image.reversesWinding()) std::reverse(v.vertices.begin(), v.vertices.end());
            for (auto& t : v.triangles) {
                for (auto& p : t) p = image.point(p);
                if (image.reversesWinding()) std::swap(t[1], t[2]);
            }
            v.normal = glm::normalize(image.direction(a.normal));
            v.centre = image.point(a.centre);
            v.moments = polygonMoments(v.triangles);
            v.luminance = a.luminance * image.weight;
            if (a.sky) {  // the sky beyond the real opening, seen through the chain
                v.skyFrame = glm::transpose(glm::dmat3(image.transform)) * a.skyFrame;
                v.skyWeight = a.skyWeight * luminance(image.weight);
                v.luminance = Rgb(luminance(v.luminance));  // daylight is grey
            }
            mirrored.push_back(std::move(v));
        }
        m_imageAreaLights.push_back(std::move(mirrored));
    }
}

double DirectLight::emittedFlux() const {
    double flux = 0;
    for (size_t k = 0; k < m_pointLights.size(); ++k) {
        const scene::PointLight& l = m_pointLights[k];
        if (static_cast<int>(k) == m_sun) {
            if (m_enteringMeasured) continue;  // in the measured flux
            // The sun's flux: what it sends in through the openings, E_n τ(θ) cosθ A.
            for (size_t i : m_openings) {
                const AreaLight& o = m_areaLights[i];
                const double c = -glm::dot(m_daylight->sunDirection, o.normal);
                if (c > 0)
                    flux += m_daylight->sunNormalIlluminance * scene::glazingTransmittance(o.transmittance, c) * c * o.area;
            }
        } else if (l.photometry) {
            flux += luminance(l.intensity) * l.photometricFlux;  // the file's table, integrated
        } else if (!l.isSpot) {
            flux += 4 * kPi * luminance(l.intensity);  // Φ = 4π I
        } else {
            // Φ = 2π ∫ I(θ) sinθ dθ over the cone, numerically (midpoint rule).
            Vec3 side = std::abs(l.direction.x) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
            Vec3 perp = glm::normalize(glm::cross(l.direction, side));
            const int n = 4096;
            double sum = 0;
            for (int i = 0; i < n; ++i) {
                double theta = (i + 0.5) * kPi / n;
                Vec3 w = std::cos(theta) * l.direction + std::sin(theta) * perp;
                sum += luminance(l.intensityToward(w)) * std::sin(theta);
            }
            flux += 2 * kPi * sum * kPi / n;
        }
    }
    for (const auto& a : m_areaLights)
        if (!a.sky || !m_enteringMeasured) flux += kPi * luminance(a.luminance) * a.area;  // Φ = π L A
    if (m_enteringMeasured) flux += *m_enteringMeasured;
    return flux;
}

Rgb DirectLight::pointSourceIntensityToward(size_t s, const Vec3& x) const {
    const Vec3 d = x - pointSourcePosition(s);
    const double r = glm::length(d);
    return r > 0 ? pointSourceIntensityAlong(s, d / r) : Rgb(0.0);
}

Rgb DirectLight::pointSourceIntensityAlong(size_t s, const Vec3& w) const {
    const scene::PointLight& l = m_pointLights[s % perChain()];
    if (s < perChain()) return l.intensityToward(w);
    // An image's transform is a product of reflections: its linear part is orthogonal, so
    // the direction leaving the real light is the transpose applied to the unfolded one.
    const MirrorImage& image = m_images[s / perChain() - 1];
    const Vec3 leaving = glm::transpose(glm::dmat3(image.transform)) * w;
    return l.intensityToward(leaving) * image.weight;
}

Vec3 DirectLight::pointSourcePosition(size_t s) const {
    const Vec3& p = m_pointLights[s % perChain()].position;
    return s < perChain() ? p : m_images[s / perChain() - 1].point(p);
}

namespace {
/// E = I(ω) cosθ / d² at x from a source at p sending l's distribution.
Rgb pointIlluminance(const scene::PointLight& l, const Vec3& p, const Vec3& x, const Vec3& n) {
    Vec3 d = p - x;
    double r2 = glm::dot(d, d);
    if (r2 <= 0) return Rgb(0.0);
    double r = std::sqrt(r2);
    double cosTheta = glm::dot(n, d) / r;
    if (cosTheta <= 0) return Rgb(0.0);
    return l.intensityToward(-d / r) * (cosTheta / r2);
}
}  // namespace

bool DirectLight::inNearField(const scene::PointLight& l, const Vec3& x, double sizes) {
    return !l.openingPoints.empty() && glm::length(x - l.position) < sizes * l.openingSize;
}

Rgb DirectLight::unshadowedFromPointLight(const scene::PointLight& l, const Vec3& x, const Vec3& n) const {
    if (!inNearField(l, x)) return pointIlluminance(l, l.position, x, n) * glazingFor(l, x);
    Rgb sum(0.0);  // the opening's parts, each with 1/n of the distribution
    for (const Vec3& p : l.openingPoints) sum += pointIlluminance(l, p, x, n);
    return sum / static_cast<double>(l.openingPoints.size());
}

Rgb DirectLight::fromPointLight(const scene::PointLight& l, const Vec3& x, const Vec3& n, const Visibility& vis) const {
    if (inNearField(l, x)) {
        Rgb sum(0.0);
        for (const Vec3& p : l.openingPoints) {
            const Rgb e = pointIlluminance(l, p, x, n);
            if (e != Rgb(0.0) && vis.visibleFromSurface(x, n, p)) sum += e;
        }
        return sum / static_cast<double>(l.openingPoints.size());
    }
    const Rgb e = unshadowedFromPointLight(l, x, n);  // the sun's through its glazing
    if (e == Rgb(0.0) || !vis.visibleFromSurface(x, n, l.position)) return Rgb(0.0);
    return e;
}

Rgb DirectLight::fromPointImage(const scene::PointLight& l, const MirrorImage& image, const MirrorPath& path,
                                const Vec3& x, const Vec3& n) {
    Vec3 d = image.point(l.position) - x;  // the unfolded path
    double r2 = glm::dot(d, d);
    if (r2 <= 0) return Rgb(0.0);
    double cosTheta = glm::dot(n, d) / std::sqrt(r2);
    if (cosTheta <= 0) return Rgb(0.0);
    Vec3 leaving;
    if (!path.trace(image.point(l.position), x, &leaving, &n)) return Rgb(0.0);
    return l.intensityToward(leaving) * image.weight * (cosTheta / r2);  // E = Ks I cosθ / d²
}

Rgb DirectLight::fromPointSource(size_t s, const Vec3& x, const Vec3& n, const Visibility& vis) const {
    const scene::PointLight& light = m_pointLights[s % perChain()];
    if (s < perChain()) return fromPointLight(light, x, n, vis);
    const MirrorImage& image = m_images[s / perChain() - 1];
    return fromPointImage(light, image, MirrorPath(m_mirrors, image, vis), x, n);
}

const AreaLight& DirectLight::areaSource(size_t s) const {
    const size_t k = s % perChain() - m_pointLights.size();
    return s < perChain() ? m_areaLights[k] : m_imageAreaLights[s / perChain() - 1][k];
}

Rgb DirectLight::fromAreaSource(size_t s, const Vec3& x, const Vec3& n, const Visibility& vis, int samples,
                                Random* rng) const {
    if (s < perChain()) return fromAreaLight(areaSource(s), x, n, vis, samples, rng);
    const size_t i = s / perChain() - 1, k = s % perChain() - m_pointLights.size();
    return fromAreaImage(i, k, x, n, MirrorPath(m_mirrors, m_images[i], vis), samples, rng);
}

Rgb DirectLight::fromOpeningWithSkyFactor(size_t s, const Vec3& x, const Vec3& n, const Visibility& vis, int samples,
                                          Random* rng, double skyFactor) const {
    const AreaLight& light = areaSource(s);
    if (s >= perChain() || !light.sky) return fromAreaSource(s, x, n, vis, samples, rng);
    const double f = areaLightFormFactor(light, x, n);
    if (f <= 0) return Rgb(0.0);
    return light.luminance * (kPi * f * skyFactor * visibleFraction(light, x, n, &vis, samples, rng));
}

std::optional<AreaLight> DirectLight::visiblePartOfImage(size_t i, size_t k, const Vec3& x) const {
    const AreaLight& light = m_imageAreaLights[i][k];
    if (glm::dot(light.normal, x - light.centre) <= 0) return std::nullopt;  // behind the emitting side
    if (!m_convexMirrors) return light;
    if (!m_images[i].mayPassToPoint(light.centre, light.radius, x)) return std::nullopt;  // cheaper than clipping
    auto part = clipToApertures(m_images[i], light.vertices, x);
    if (part.empty()) return std::nullopt;
    AreaLight visible = makeAreaLight(std::move(part), light.normal, light.luminance);
    visible.sky = light.sky, visible.transmittance = light.transmittance;
    visible.skyFrame = light.skyFrame, visible.skyWeight = light.skyWeight;
    return visible;
}

Rgb DirectLight::fromAreaImage(size_t i, size_t k, const Vec3& x, const Vec3& n, const MirrorPath& path, int samples,
                               Random* rng, Rgb* open) const {
    // Nothing of the image in front of the receiver's plane: no light, and no clipping.
    bool inFront = false;
    for (const Vec3& v : m_imageAreaLights[i][k].vertices) inFront |= glm::dot(n, v - x) > 0;
    const auto part = inFront ? visiblePartOfImage(i, k, x) : std::nullopt;
    if (part) return fromAreaLight(*part, x, n, path, samples, rng, open);
    if (open) *open = Rgb(0.0);
    return Rgb(0.0);
}

Rgb DirectLight::unshadowedFromAreaSource(size_t s, const Vec3& x, const Vec3& n, bool withSky) const {
    auto open = [&](const AreaLight& light) {
        if (light.luminance == Rgb(0.0)) return Rgb(0.0);
        if (light.sky && withSky) {
            double sky = 0;
            throughOpening(light, x, n, nullptr, 0, nullptr, &sky);  // at least kOpeningSamples parts
            return Rgb(sky);
        }
        return light.luminance * (kPi * areaLightFormFactor(light, x, n));  // E = π L F
    };
    if (s < perChain()) return open(areaSource(s));
    const auto part = visiblePartOfImage(s / perChain() - 1, s % perChain() - m_pointLights.size(), x);
    return part ? open(*part) : Rgb(0.0);
}

ApertureCover DirectLight::apertureCover(size_t s, const std::array<Vec3, 3>& t) const {
    CHECK(isPointSource(s));
    if (s < perChain()) return ApertureCover::Whole;
    const MirrorImage& image = m_images[s / perChain() - 1];
    const Vec3 y = pointSourcePosition(s);  // the image, behind the chain's last mirror

    // None: t behind the last mirror, or outside the plane through one of its edges and y.
    const scene::Mirror& last = m_mirrors[image.chain.back()];
    bool triangleBehind = true;
    for (const Vec3& x : t) triangleBehind &= last.side(x) <= 0;
    if (triangleBehind) return ApertureCover::None;
    if (last.side(y) < 0) {
        const size_t n = last.polygon.size();
        for (size_t e = 0; e < n; ++e) {
            const Vec3& a = last.polygon[e];
            const Vec3 edge = last.polygon[(e + 1) % n] - a;
            // det(edge, y − a, x − a) > 0 on the polygon's side of the plane through the
            // edge and y, for y behind a counter-clockwise polygon (seen from its front).
            bool allOutside = true;
            for (const Vec3& x : t) allOutside &= glm::dot(glm::cross(edge, y - a), x - a) < 0;
            if (allOutside) return ApertureCover::None;
        }
    }
    for (const Vec3& x : t)
        if (!throughApertures(m_mirrors, image, y, x)) return ApertureCover::Partial;
    return ApertureCover::Whole;
}

Rgb DirectLight::illuminance(const Vec3& x, const Vec3& n, const Visibility& vis, int samples, Random* rng,
                             std::vector<Rgb>* perSource, std::vector<Rgb>* perSourceOpen) const {
    const size_t points = m_pointLights.size();
    if (perSource) perSource->assign(sourceCount(), Rgb(0.0));
    if (perSourceOpen) perSourceOpen->assign(sourceCount(), Rgb(0.0));
    auto openOf = [&](size_t s) { return perSourceOpen ? &(*perSourceOpen)[s] : nullptr; };
    Rgb e(0.0);
    auto add = [&](size_t s, const Rgb& value) {
        if (perSource) (*perSource)[s] = value;
        e += value;
    };
    for (size_t k = 0; k < points; ++k) add(k, fromPointLight(m_pointLights[k], x, n, vis));
    for (size_t k = 0; k < m_areaLights.size(); ++k)
        add(points + k, fromAreaLight(m_areaLights[k], x, n, vis, samples, rng, openOf(points + k)));
    return e + fromImages(x, n, vis, samples, rng, perSource, perSourceOpen);
}

Rgb DirectLight::fromImages(const Vec3& x, const Vec3& n, const Visibility& vis, int samples, Random* rng,
                            std::vector<Rgb>* perSource, std::vector<Rgb>* perSourceOpen) const {
    const size_t points = m_pointLights.size();
    Rgb e(0.0);
    for (size_t i = 0; i < m_images.size(); ++i) {
        MirrorPath path(m_mirrors, m_images[i], vis);
        const size_t chain = (i + 1) * perChain();
        for (size_t k = 0; k < points; ++k) {
            const Rgb v = fromPointImage(m_pointLights[k], m_images[i], path, x, n);
            if (perSource) (*perSource)[chain + k] = v;
            e += v;
        }
        for (size_t k = 0; k < m_areaLights.size(); ++k) {
            const size_t s = chain + points + k;
            const Rgb v = fromAreaImage(i, k, x, n, path, samples, rng, perSourceOpen ? &(*perSourceOpen)[s] : nullptr);
            if (perSource) (*perSource)[s] = v;
            e += v;
        }
    }
    return e;
}

Rgb DirectLight::fromAreaLight(const AreaLight& light, const Vec3& x, const Vec3& n, const Visibility& vis, int samples,
                               Random* rng, Rgb* open, double* visible) const {
    const double f = light.luminance == Rgb(0.0) ? 0.0 : areaLightFormFactor(light, x, n);
    if (open) *open = light.luminance * (kPi * std::max(0.0, f));
    if (visible) *visible = 0;
    if (f <= 0) return Rgb(0.0);
    if (light.sky) {  // an opening: the sky through its parts
        double unshadowed = 0;
        const double e = throughOpening(light, x, n, &vis, samples, rng, &unshadowed);
        if (open) *open = Rgb(unshadowed);
        if (visible) *visible = unshadowed > 0 ? e / unshadowed : 0.0;
        return Rgb(e);
    }
    const double v = visibleFraction(light, x, n, &vis, samples, rng);
    if (visible) *visible = v;
    return light.luminance * (kPi * f * v);  // E = π L F
}

double DirectLight::visibleFraction(const AreaLight& light, const Vec3& x, const Vec3& n, const Visibility* vis,
                                    int samples, Random* rng) const {
    // Visible fraction, weighted by the unoccluded integrand cosθ_x cosθ_y / r².
    const double near = kAllSamplesDiameters * 2 * light.radius;  // m
    const double d2 = glm::dot(light.centre - x, light.centre - x);
    const double rays = d2 > near * near ? samples * near * near / d2 : samples;
    CHECK(vis);
    double weightSum = 0, visibleSum = 0;
    RayBatch<double> shadowRays(*vis, x, n, visibleSum);  // the samples' rays, traced together
    auto sample = [&](const std::array<Vec3, 3>& tri, double u1, double u2) {
        // Uniform point on a triangle (square-root warp).
        const double su = std::sqrt(u1);
        const Vec3 y = (1 - su) * tri[0] + su * (1 - u2) * tri[1] + su * u2 * tri[2];
        const Vec3 d = y - x;
        const double r2 = glm::dot(d, d);
        if (r2 <= 0) return;
        // cosθ_x cosθ_y / r² = (n·d)(−N·d) / r⁴, for an opening times the sky's L τ along d
        double w = std::max(0.0, glm::dot(n, d)) * std::max(0.0, -glm::dot(light.normal, d)) / (r2 * r2);
        if (w <= 0) return;
        if (light.sky) w *= light.skyLuminanceAlong(d / std::sqrt(r2));
        weightSum += w;
        shadowRays.add(y, w);
    };
    if (rays < static_cast<double>(light.triangles.size())) {
        // Fewer rays than triangles (a far light): stratified over the whole outline by area.
        const int count = std::max(1, static_cast<int>(std::lround(rays)));
        for (int i = 0; i < count; ++i) {
            double u = (i + (rng ? rng->nextDouble() : 0.5)) / count * light.area;  // m², along the triangles
            size_t t = 0;
            while (t + 1 < light.triangles.size() && u > light.triangleAreas[t]) u -= light.triangleAreas[t++];
            const double u2 = rng ? rng->nextDouble() : 0.5;
            sample(light.triangles[t], std::clamp(u / light.triangleAreas[t], 0.0, 1.0), u2);
        }
    } else {
        for (size_t t = 0; t < light.triangles.size(); ++t) {
            int nt = std::max(1, static_cast<int>(std::lround(rays * light.triangleAreas[t] / light.area)));
            int m = std::max(1, static_cast<int>(std::ceil(std::sqrt(static_cast<double>(nt)))));
            for (int i = 0; i < m; ++i)
                for (int j = 0; j < m; ++j) {
                    const double u1 = (i + (rng ? rng->nextDouble() : 0.5)) / m;  // drawn in this order
                    const double u2 = (j + (rng ? rng->nextDouble() : 0.5)) / m;
                    sample(light.triangles[t], u1, u2);
                }
        }
    }
    shadowRays.flush();
    return weightSum > 0 ? visibleSum / weightSum : 1.0;
}

}  // namespace rayrad::radiosity
