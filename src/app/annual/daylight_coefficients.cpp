#include <app/annual/daylight_coefficients.h>

#include <core/input_error.h>
#include <core/progress.h>
#include <core/stage_report.h>
#include <scene/light_groups.h>
#include <scene/polygon.h>
#include <scene/daylight/glazing.h>

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <optional>
#include <unordered_map>

#include <tbb/parallel_for.h>

namespace rayrad::app {

namespace {

/// Solves the lighting of run.scene as it is now (its daylight one channel), reusing and
/// handing back the clusters; the sensors' values, or nothing when no light comes in.
std::optional<std::vector<radiosity::SensorValue>> solveChannel(PipelineRun& run, radiosity::Clustering& clusters) {
    const radiosity::StageLog log{nullptr, nullptr, true, nullptr};
    radiosity::Lighting lighting = radiosity::solveDirect(run.scene, run.mesh, *run.embree, log);
    // No opening faces this sky (its unobstructed light through each, exactly), or the
    // sun reaches no point of any opening: nothing comes in.
    if (lighting.lights->openingCount() == 0 || !(lighting.lights->emittedFlux() > 0)) return std::nullopt;
    lighting.clustering = std::move(clusters);
    radiosity::solveIndirect(run.scene, run.mesh, *run.embree, lighting, log);
    auto values = radiosity::gatherSensors(run.scene, run.mesh, *run.embree, lighting, log);
    clusters = std::move(lighting.clustering);
    return values;
}

}  // namespace

DaylightCoefficients solveDaylightCoefficients(PipelineRun& run, std::shared_ptr<const scene::SkyPatches> patches,
                                               std::shared_ptr<const scene::SkyPatches> fine,
                                               const std::vector<char>& sunNear, bool quiet) {
    if (!run.scene.daylight)
        throw InputError(placeMessage(run.scene.file, "", "an annual study needs the scene's \"daylight\" (its axes "
                                                          "and ground) and openings"));
    const auto start = std::chrono::steady_clock::now();
    const double cpuStart = processCpuSeconds();
    DaylightCoefficients dc;
    dc.patches = std::move(patches);
    dc.points = run.scene.sensors.size();
    dc.indirect.assign(static_cast<size_t>(dc.channels()) * dc.points, 0.0);
    dc.sunSlot.assign(static_cast<size_t>(dc.patches->count()), -1);
    int suns = 0;
    for (char c : sunNear) suns += c != 0;

    scene::removeElectricLight(run.scene);
    const scene::Daylight base = *run.scene.daylight;
    radiosity::Clustering clusters;  // geometry only: built by the first channel, shared by the rest
    Progress progress("daylight coefficients", quiet);
    const int total = dc.channels() + suns;
    int done = 0;
    for (int c = 0; c < dc.channels(); ++c, ++done) {
        progress.update(static_cast<double>(done) / total, fmt::format("sky channel {} of {}", c + 1, dc.channels()));
        const int patch = c == dc.groundChannel() ? scene::SkyChannel::kGround : c;
        run.scene.daylight = scene::channelDaylight(base, {dc.patches, patch});
        const auto values = solveChannel(run, clusters);
        if (!values) continue;
        ++dc.solvedChannels;
        for (size_t i = 0; i < values->size(); ++i)
            dc.indirect[static_cast<size_t>(c) * dc.points + i] = luminance((*values)[i].indirect);
    }
    for (int j = 0; j < dc.patches->count(); ++j) {
        if (!sunNear[static_cast<size_t>(j)]) continue;
        progress.update(static_cast<double>(done++) / total, fmt::format("sun {} of {}", done - dc.channels(), suns));
        run.scene.daylight = scene::sunChannelDaylight(base, dc.patches->centre(j));
        const auto values = solveChannel(run, clusters);
        if (!values) continue;
        dc.sunSlot[static_cast<size_t>(j)] = dc.solvedSuns++;
        for (const auto& v : *values) dc.sunIndirect.push_back(luminance(v.indirect));
    }
    run.scene.daylight = base;
    dc.skyDirect = directSkyCoefficients(run, std::move(fine));
    dc.solveCpuSeconds = processCpuSeconds() - cpuStart;
    dc.solveWallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return dc;
}

std::vector<OpeningSamples> openingSamples(const scene::Scene& scene, int perSide) {
    std::vector<OpeningSamples> out;
    for (const auto& g : scene.groups) {
        const auto& mat = scene.materials[g.material];
        if (!mat.isOpening()) continue;
        for (const auto& poly : g.polygons) {
            std::vector<Vec3> v;
            for (uint32_t i : poly) v.push_back(g.positions[i]);
            OpeningSamples o;
            o.out = -scene::polygonNormal(v);  // an opening's front faces the room
            o.transmittance = mat.transmittance;
            o.area = scene::polygonArea(v);
            const auto triangles = scene::triangulate(v);
            for (const auto& t : triangles) {
                const double area = 0.5 * glm::length(glm::cross(v[t[1]] - v[t[0]], v[t[2]] - v[t[0]]));
                const double share = o.area > 0 ? area / o.area : 0.0;
                const int n = std::max(1, static_cast<int>(std::lround(perSide * std::sqrt(share * triangles.size()))));
                // The n × n cells of the unit square onto the triangle, equal areas to equal
                // areas: (1 − √u) A + √u (1 − w) B + √u w C.
                for (int a = 0; a < n; ++a)
                    for (int b = 0; b < n; ++b) {
                        const double su = std::sqrt((a + 0.5) / n), w = (b + 0.5) / n;
                        o.points.push_back((1 - su) * v[t[0]] + su * (1 - w) * v[t[1]] + su * w * v[t[2]]);
                        o.pointArea.push_back(area / (n * n));
                    }
            }
            out.push_back(std::move(o));
        }
    }
    return out;
}

namespace {
scene::Scene uniformSkyScene(const scene::Scene& s) {
    scene::Scene copy = s;
    scene::Daylight& d = *copy.daylight;
    d.channel.reset();
    d.sun.reset();
    d.sunNormalIlluminance = 0;
    d.perez.reset();
    d.kind = scene::SkyKind::Uniform;
    scene::finishDaylight(d, 1.0, 0.0);
    return copy;
}
}  // namespace

SunLight::SunLight(const PipelineRun& run, const scene::SkyPatches& patches)
    : m_run(run),
      m_openingLights(std::make_unique<radiosity::DirectLight>(uniformSkyScene(run.scene))),
      m_far(4 * std::max(run.scene.diagonal(), 1.0)) {
    const scene::Scene& sc = run.scene;
    m_openings = openingSamples(sc, 8);
    const scene::Daylight& d = *sc.daylight;
    for (int j = 0; j < patches.count(); ++j) {
        const Vec3 l = patches.centre(j);
        m_nodeEntering.push_back(entering(glm::normalize(l.x * d.east + l.y * d.north + l.z * d.up)));
    }
}

SunLight::~SunLight() = default;

DirectSkyCoefficients directSkyCoefficients(const PipelineRun& run, std::shared_ptr<const scene::SkyPatches> fine) {
    const double cpuStart = processCpuSeconds();
    DirectSkyCoefficients out;
    out.patches = std::move(fine);
    const scene::Scene& sc = run.scene;
    const scene::Daylight& d = *sc.daylight;
    const auto openings = openingSamples(sc, 32);
    const radiosity::DirectLight glazings(uniformSkyScene(sc));
    const double far = 4 * std::max(sc.diagonal(), 1.0);
    const uint32_t ground = static_cast<uint32_t>(out.patches->count());
    out.terms.resize(sc.sensors.size());
    tbb::parallel_for(size_t(0), sc.sensors.size(), [&](size_t i) {
        const Vec3 x = sc.sensors[i].position, n = sc.sensors[i].normal;
        std::unordered_map<uint32_t, double> sum;
        for (const OpeningSamples& o : openings)
            for (size_t k = 0; k < o.points.size(); ++k) {
                const Vec3 dy = o.points[k] - x;
                const double r2 = glm::dot(dy, dy);
                if (!(r2 > 0)) continue;
                const Vec3 w = dy / std::sqrt(r2);
                const double cx = glm::dot(n, w), cy = glm::dot(w, o.out);
                if (cx <= 0 || cy <= 0) continue;
                const double tau = glazings.openingTransmittance(x, w, far);
                if (!(tau > 0) || !run.embree->visibleFromSurface(x, n, x + far * w)) continue;
                const double e = tau * cx * cy * o.pointArea[k] / r2;  // lx per cd/m²
                const Vec3 local = d.toLocal(w);
                if (local.z < 0) {
                    sum[ground] += e;
                    continue;
                }
                const auto t = out.patches->weights(local);
                for (int j = 0; j < t.count; ++j) sum[static_cast<uint32_t>(t.patch[j])] += e * t.weight[j];
            }
        auto& terms = out.terms[i];
        for (const auto& [tent, e] : sum)
            if (e > 0) terms.emplace_back(tent, static_cast<float>(e));
        std::sort(terms.begin(), terms.end());
    });
    out.cpuSeconds = processCpuSeconds() - cpuStart;
    return out;
}

double SunLight::entering(const Vec3& toSky) const {
    double flux = 0;
    for (const OpeningSamples& o : m_openings) {
        const double c = glm::dot(toSky, o.out);
        if (c <= 0 || o.points.empty()) continue;
        size_t clear = 0;
        for (const Vec3& y : o.points) clear += m_run.embree->visible(y, y + m_far * toSky);
        flux += o.area * scene::glazingTransmittance(o.transmittance, c) * c * clear / o.points.size();
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
