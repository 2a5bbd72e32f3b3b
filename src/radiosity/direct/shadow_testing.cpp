// Adaptive shadow testing for display (Ward, "Adaptive shadow testing for ray tracing",
// Eurographics Rendering Workshop 1991): with a hundred luminaires, most of a hit point's
// light comes from a few of them, and the rest need not each cast shadow rays.
#include <radiosity/direct/direct_light.h>

#include <radiosity/form_factors/form_factor.h>

#include <algorithm>
#include <cmath>

namespace rayrad::radiosity {

namespace {
/// Beyond this many of its diameters an area light's unshadowed illuminance is ranked by
/// the point approximation L A cosθ_x cosθ_y / r² (a light that is tested gets its
/// analytic or second-order F: areaLightFormFactor).
constexpr double kRankPointDiameters = 5.0;

/// The point approximation of an area light's π F at x, about its centre:
/// A cosθ_x cosθ_y / r² (lx per cd/m²).
double pointAreaFactor(const AreaLight& light, const Vec3& x, const Vec3& n) {
    const Vec3 d = light.centre - x;
    const double r2 = glm::dot(d, d);
    // cosθ_x cosθ_y / r² = (n·d)(−N·d) / r⁴
    const double nd = glm::dot(n, d), ld = -glm::dot(light.normal, d);
    return nd > 0 && ld > 0 ? light.area * nd * ld / (r2 * r2) : 0.0;
}

/// An area light's unshadowed illuminance at x over its luminance (lx per cd/m²), for
/// ranking and for the untested: π F with the analytic F (`exact`, near) or the point
/// approximation (far).
double unshadowedAreaFactor(const AreaLight& light, const Vec3& x, const Vec3& n, bool& exact) {
    const Vec3 d = light.centre - x;
    const double far = kRankPointDiameters * 2 * light.radius;
    exact = glm::dot(d, d) <= far * far;
    if (!exact) return pointAreaFactor(light, x, n);
    const double f =
        formFactorToPolygon(x, n, light.vertices.data(), static_cast<int>(light.vertices.size()), light.normal);
    return kPi * std::max(0.0, f);  // π F
}
}  // namespace

Rgb DirectLight::illuminanceForDisplay(const Vec3& x, const Vec3& n, const Visibility& vis, int samples, Random* rng,
                                       double threshold, double received, PixelLightMemo* pixel, int64_t patch) const {
    if (threshold <= 0) return illuminance(x, n, vis, samples, rng);
    if (pixel && patch >= 0 && pixel->patch == patch) return fromPixelMemo(*pixel, x, n, vis, samples, rng);
    if (pixel) {
        pixel->patch = patch;
        pixel->retested.clear();
        pixel->far.clear();
    }
    struct Candidate {
        double potential;  ///< Y of the unshadowed illuminance, lx
        double factor;     ///< the unshadowed illuminance over the light's colour (colourOf)
        uint32_t light;    ///< points first, then area lights
        bool exact;        ///< a point light, or π F analytic
    };
    thread_local std::vector<Candidate> candidates;
    candidates.clear();
    const size_t points = m_pointLights.size();
    double remaining = 0;  // Σ potential of the lights not yet tested
    // A light's colour: a point light's intensity, an area light's luminance (cd, cd/m²);
    // its unshadowed illuminance at x is that colour times a factor.
    auto colourOf = [&](uint32_t light) {
        return light < points ? m_pointLights[light].intensity : m_areaLights[light - points].luminance;
    };
    for (size_t k = 0; k < points; ++k) {
        const double y = luminance(unshadowedFromPointLight(m_pointLights[k], x, n));
        if (y > 0)
            candidates.push_back({y, y / luminance(colourOf(k)), static_cast<uint32_t>(k), true}), remaining += y;
    }
    for (size_t k = 0; k < m_areaLights.size(); ++k) {
        bool exact = false;
        const double factor = unshadowedAreaFactor(m_areaLights[k], x, n, exact);
        const double y = luminance(m_areaLights[k].luminance) * factor;
        if (y > 0) candidates.push_back({y, factor, static_cast<uint32_t>(points + k), exact}), remaining += y;
    }
    // The strongest first (ties: the lower index, so the order is deterministic), taken
    // from a heap: a hit tests only part of its lights (in the bench hall 16 of the 37 in
    // front of it, of 100), and sorting them all cost more than the selection.
    auto weaker = [](const Candidate& a, const Candidate& b) {
        return a.potential != b.potential ? a.potential < b.potential : a.light > b.light;
    };
    std::make_heap(candidates.begin(), candidates.end(), weaker);
    auto untestedEnd = candidates.end();  // [begin, untestedEnd) is the heap of lights not yet tested
    // Test the strongest first, until what is left could add less than the threshold of
    // all x receives: the light found, and what it receives besides (a spot under a desk,
    // where every light is blocked, need not test them all to be within the threshold).
    Rgb e(0.0);
    double found = 0, tested = 0;  // Y of what the tested lights gave, and of their potential
    for (; untestedEnd != candidates.begin(); --untestedEnd) {
        if (untestedEnd != candidates.end() && remaining < threshold * (found + received)) break;
        std::pop_heap(candidates.begin(), untestedEnd, weaker);
        const Candidate& c = *(untestedEnd - 1);
        Rgb v;
        if (c.light < points) {
            v = fromPointLight(m_pointLights[c.light], x, n, vis);
        } else if (c.exact && !m_areaLights[c.light - points].sky) {
            const AreaLight& light = m_areaLights[c.light - points];
            v = light.luminance * (c.factor * visibleFraction(light, x, n, &vis, samples, rng));
        } else {  // an opening (the sky through its parts), or a far lamp: its visible fraction is kept
            double visible = 0;
            Rgb open(0.0);
            v = fromAreaLight(m_areaLights[c.light - points], x, n, vis, samples, rng, &open, &visible);
            // c.factor is its point approximation A cosθ_x cosθ_y / r² = π F_point (> 0: a candidate).
            if (pixel && !c.exact)
                pixel->far.push_back({c.light, visible * luminance(open) / (luminance(colourOf(c.light)) * c.factor)});
        }
        if (pixel && (c.light < points || c.exact)) pixel->retested.push_back(c.light);
        e += v;
        found += luminance(v);
        tested += c.potential;
        remaining -= c.potential;
    }
    // The untested: unshadowed, times the share of their potential the tested lights delivered.
    const double seen = tested > 0 ? std::min(1.0, found / tested) : 1.0;
    Rgb untested(0.0);
    for (auto c = candidates.begin(); c != untestedEnd; ++c) untested += colourOf(c->light) * (c->factor * seen);
    if (pixel) pixel->untested = untested;
    return e + untested + fromImages(x, n, vis, samples, rng, nullptr, nullptr);
}

Rgb DirectLight::fromPixelMemo(const PixelLightMemo& pixel, const Vec3& x, const Vec3& n, const Visibility& vis,
                               int samples, Random* rng) const {
    const size_t points = m_pointLights.size();
    Rgb e = pixel.untested;  // far lights: it changes by the footprint's size over their distance
    for (uint32_t k : pixel.retested) {
        if (k < points) {
            e += fromPointLight(m_pointLights[k], x, n, vis);
            continue;
        }
        e += fromAreaLight(m_areaLights[k - points], x, n, vis, samples, rng);  // near: Lambert's F, own rays
    }
    for (const PixelLightMemo::Far& f : pixel.far) {
        const AreaLight& light = m_areaLights[f.light - points];
        e += light.luminance * (pointAreaFactor(light, x, n) * f.scale);  // the ratio was taken to this
    }
    return e + fromImages(x, n, vis, samples, rng, nullptr, nullptr);
}

}  // namespace rayrad::radiosity
