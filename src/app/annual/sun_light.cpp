#include <app/annual/sun_light.h>

#include <scene/daylight/glazing.h>

#include <cmath>

namespace rayrad::app {

SunLight::SunLight(const PipelineRun& run, const scene::SkyPatches& patches)
    : m_run(run),
      m_openingLights(openingGlazings(run.scene)),
      m_far(4 * std::max(run.scene.diagonal(), 1.0)) {
    const scene::Scene& sc = run.scene;
    m_openings = openingSamples(sc, 8);
    const scene::Daylight& d = *sc.daylight;
    for (int j = 0; j < patches.count(); ++j) {
        const Vec3 l = patches.centre(j);
        m_nodeEntering.push_back(entering(glm::normalize(d.toWorld(l))));
    }
}

SunLight::~SunLight() = default;

double SunLight::entering(const Vec3& toSky) const {
    double flux = 0;
    for (const OpeningSamples& o : m_openings) {
        const double c = glm::dot(toSky, o.out);
        if (c <= 0 || o.points.empty()) continue;
        double clear = 0;  // m²
        for (size_t k = 0; k < o.points.size(); ++k)
            if (m_run.embree->visible(o.points[k], o.points[k] + m_far * toSky)) clear += o.pointArea[k];
        flux += clear * scene::glazingTransmittance(o.transmittance, c) * c;
    }
    return flux;
}

double SunLight::sunScale(const Vec3& toSun, const scene::SkyPatches::Weights& w) const {
    double around = 0;
    for (int k = 0; k < w.count; ++k) around += w.weight[k] * m_nodeEntering[static_cast<size_t>(w.patch[k])];
    return around > 0 ? entering(toSun) / around : 0.0;
}

double SunLight::directAt(const Vec3& x, const Vec3& n, const Vec3& toSun) const {
    const double c = glm::dot(n, toSun);
    if (c <= 0) return 0.0;
    const double tau = m_openingLights->openingTransmittance(x, toSun, m_far);
    if (!(tau > 0) || !m_run.embree->visibleFromSurface(x, n, x + 1e5 * m_far * toSun)) return 0.0;
    return c * tau;
}

}  // namespace rayrad::app
