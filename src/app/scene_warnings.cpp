#include <app/scene_warnings.h>

#include <app/coincident_surfaces.h>
#include <app/daylight_warnings.h>

#include <radiosity/radiosity.h>
#include <raytrace/camera.h>
#include <scene/polygon.h>

#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace rayrad::app {

namespace {

/// Rays per probe: a Fibonacci sphere (deterministic, nearly uniform).
constexpr int kProbeRays = 64;
/// A probe counts as enclosed when at least this fraction of its rays hits the back of a surface.
constexpr double kEnclosedFraction = 0.9;

std::vector<Vec3> sphereDirections(int n) {
    std::vector<Vec3> out;
    const double golden = kPi * (3 - std::sqrt(5.0));
    for (int i = 0; i < n; ++i) {
        double z = 1 - (2 * i + 1.0) / n, r = std::sqrt(std::max(0.0, 1 - z * z));
        out.emplace_back(r * std::cos(golden * i), r * std::sin(golden * i), z);
    }
    return out;
}

/// What the rays from a point see: hits on a surface's back side, hits closer than
/// `near`, hits on a mirror's back, and misses.
struct Probe {
    int rays = 0, backFaces = 0, nearHits = 0, mirrorBacks = 0, misses = 0;
    /// Hemisphere probes: the cosine-weighted share of the rays that hit within `near`
    /// (what a sensor's illuminance would lose).
    double nearWeight = 0, weight = 0;
    double fraction(int count) const { return rays > 0 ? double(count) / rays : 0.0; }
    double coveredFraction() const { return weight > 0 ? nearWeight / weight : 0.0; }
};

class Prober {
  public:
    Prober(const radiosity::PatchMesh& mesh, const raytrace::EmbreeScene& embree, double diagonal)
        : m_mesh(mesh), m_embree(embree), m_directions(sphereDirections(kProbeRays)), m_diagonal(diagonal) {}

    /// Rays over the sphere, or over the hemisphere about `normal` when it is non-zero.
    Probe probe(const Vec3& origin, const Vec3& normal, double near) const {
        Probe p;
        const bool hemisphere = glm::length(normal) > 0;
        const Vec3 from = hemisphere ? origin + 1e-5 * m_diagonal * normal : origin;
        for (Vec3 d : m_directions) {
            if (hemisphere && glm::dot(d, normal) < 0) d = -d;
            const double cosine = hemisphere ? glm::dot(d, normal) : 1.0;
            ++p.rays;
            p.weight += cosine;
            // tnear above 0: a sensor on an edge must not count the neighbouring wall it touches.
            raytrace::Hit h = m_embree.intersect(from, d, 1e-7 * m_diagonal, std::numeric_limits<double>::infinity());
            if (!h.found) {
                ++p.misses;
                continue;
            }
            Vec3 n = h.specular ? m_embree.specular(h.patch).normal : m_mesh.patches[h.patch].normal;
            bool back = glm::dot(n, d) > 0;
            p.backFaces += back;
            p.mirrorBacks += back && h.specular && !m_embree.specular(h.patch).glass;
            p.nearHits += h.t < near;
            if (h.t < near) p.nearWeight += cosine;
        }
        return p;
    }

  private:
    const radiosity::PatchMesh& m_mesh;
    const raytrace::EmbreeScene& m_embree;
    std::vector<Vec3> m_directions;
    double m_diagonal;
};

/// Sensors this close to a surface that faces their way (a share of the scene's diagonal)
/// but not on it (radiosity::pointNudge) are named: a position rounded off a surface.
constexpr double kNearSurfaceShare = 1e-3;

/// One line for the sensors that lie just in front of a surface facing their way but not
/// on it: they are measured where they are, in the air, and get no mesh value (what the
/// image shows there), so the two cannot be held against each other.
std::optional<std::string> offSurfaceWarning(const scene::Scene& scene, const radiosity::PatchMesh& mesh,
                                             const raytrace::EmbreeScene& embree) {
    const size_t sensors = scene.sensors.size();
    std::vector<double> offset(sensors, 0.0);  // m; 0: on a surface, or nowhere near one
    const double on = radiosity::pointNudge(scene), near = kNearSurfaceShare * scene.diagonal();
    tbb::parallel_for(size_t(0), sensors, [&](size_t i) {
        const scene::Sensor& s = scene.sensors[i];
        if (radiosity::locateOnMesh(mesh, s.position, s.normal, on, &embree)) return;
        if (auto at = radiosity::locateOnMesh(mesh, s.position, s.normal, near, &embree)) {
            const radiosity::Patch& p = mesh.patches[at->patch];
            offset[i] = std::abs(glm::dot(s.position - p.centroid, p.normal));
        }
    });
    size_t count = 0, worst = 0;
    for (size_t i = 0; i < sensors; ++i)
        if (offset[i] > 0) {
            if (count == 0 || offset[i] > offset[worst]) worst = i;
            ++count;
        }
    if (count == 0) return std::nullopt;
    return fmt::format(
        "/sensors: {} sensor(s) lie just off the surface they face, not on it (\"{}\" at {}: {:.3g} mm "
        "off): each is measured where it is, and has no mesh value to compare with the image; "
        "put it on the surface (within {:.2g} mm) to read both",
        count, scene.sensors[worst].name, toString(scene.sensors[worst].position), 1e3 * offset[worst], 1e3 * on);
}

/// One line per sensor (empty when it looks fine), in the sensors' order; `inSolid` as
/// for sceneWarnings.
std::vector<std::string> sensorWarnings(const scene::Scene& scene, const radiosity::PatchMesh& mesh,
                                        const raytrace::EmbreeScene& embree, const Prober& prober, double near,
                                        std::vector<std::string>* inSolid) {
    const double diagonal = scene.diagonal();
    auto enclosed = [](const Probe& p) { return p.fraction(p.backFaces) >= kEnclosedFraction; };
    // Each sensor probed on its own (64 rays: a million sensors took 9 CPU-s), the lines in
    // the sensors' order.
    const size_t sensors = scene.sensors.size();
    std::vector<std::string> sensorLines(sensors);
    if (inSolid) inSolid->assign(sensors, std::string());
    tbb::parallel_for(size_t(0), sensors, [&](size_t i) {
        const scene::Sensor& s = scene.sensors[i];
        // As the gather sees it: on a surface's rim, from just inside the sensor's patch.
        Vec3 x = s.position;
        if (auto at = radiosity::locateOnMesh(mesh, x, s.normal, 1e-6 * diagonal, &embree))
            if (radiosity::onSurfaceBoundary(mesh, *at, 1e-5 * diagonal, &embree))
                x = radiosity::nudgeInside(mesh, at->patch, x, 1e-6 * diagonal);
        Probe p = prober.probe(x, s.normal, near);
        std::string inside;  // why it is no measurement
        if (p.fraction(p.mirrorBacks) >= 0.5)
            sensorLines[i] = fmt::format(
                "/sensors: sensor \"{}\" at {} is behind a mirror ({} of {} hemisphere rays "
                "hit its back): it will read about 0",
                s.name, toString(s.position), p.mirrorBacks, p.rays);
        else if (p.coveredFraction() >= kEnclosedFraction) {
            inside = "buried";
            sensorLines[i] = fmt::format(
                "/sensors: sensor \"{}\" at {} is buried: {:.0f} % of its view (cosine-weighted) "
                "meets a surface within {:.3g} m, so it will read about 0 (check its position "
                "and normal)",
                s.name, toString(s.position), 100 * p.coveredFraction(), near);
        } else if (enclosed(p)) {
            inside = "inside a solid";
            sensorLines[i] = fmt::format(
                "/sensors: sensor \"{}\" at {} is inside a solid ({} of {} hemisphere rays hit "
                "the inside of surfaces): it will read about 0",
                s.name, toString(s.position), p.backFaces, p.rays);
        }
        if (!inside.empty() && !s.grid.empty()) sensorLines[i] += "; left out of its grid's statistics";
        if (inSolid) (*inSolid)[i] = inside;
    });
    return sensorLines;
}

}  // namespace

std::vector<std::string> sceneWarnings(const scene::Scene& scene, const radiosity::PatchMesh& mesh,
                                       const raytrace::EmbreeScene& embree, bool checkSensors,
                                       std::vector<std::string>* inSolid) {
    std::vector<std::string> out = scene.warnings.fileWarnings;
    if (auto w = coincidentSurfacesWarning(scene, mesh)) out.push_back(std::move(*w));
    for (auto& w : daylightWarnings(scene, embree)) out.push_back(std::move(w));
    const double diagonal = scene.diagonal();
    const double near = std::max(5e-3, 1e-4 * diagonal);  // "buried": covered within a few mm
    Prober prober(mesh, embree, diagonal);
    auto enclosed = [](const Probe& p) { return p.fraction(p.backFaces) >= kEnclosedFraction; };

    for (size_t i = 0; i < scene.lights.size(); ++i) {
        const auto& l = scene.lights[i];
        Probe p = prober.probe(l.position, Vec3(0.0), near);
        if (enclosed(p))
            out.push_back(fmt::format(
                "{}: the light at {} is inside a closed solid ({} of {} rays from it hit the "
                "inside of surfaces): its light reaches nothing",
                l.where.empty() ? fmt::format("/lights/{}", i) : l.where, toString(l.position), p.backFaces, p.rays));
    }
    for (const auto& g : scene.groups) {
        if (!scene.materials[g.material].isEmissive()) continue;
        for (const auto& poly : g.polygons) {
            std::vector<Vec3> v;
            for (uint32_t k : poly) v.push_back(g.positions[k]);
            Vec3 c(0.0);
            for (const auto& x : v) c += x;
            c /= static_cast<double>(v.size());
            Probe p = prober.probe(c, scene::polygonNormal(v), near);
            if (enclosed(p) || p.fraction(p.nearHits) >= kEnclosedFraction) {
                out.push_back(
                    fmt::format("{}: an emitter at {} faces the inside of a solid or a surface within {:.3g} m: "
                                "its light reaches almost nothing",
                                g.where, toString(c), near));
                break;  // one line per object
            }
        }
    }
    if (scene.camera) {
        const auto& cam = *scene.camera;
        Probe p = prober.probe(cam.position, Vec3(0.0), near);
        if (enclosed(p))
            out.push_back(
                fmt::format("/camera: the camera at {} is inside a closed solid ({} of {} rays hit the "
                            "inside of surfaces): the image will show only those",
                            toString(cam.position), p.backFaces, p.rays));
        // What the view itself shows: rays through a grid of image points.
        raytrace::ImageCamera camera(cam);
        int rays = 0, mirrorBacks = 0, misses = 0;
        for (int y = 0; y < 8; ++y)
            for (int x = 0; x < 8; ++x) {
                const raytrace::CameraRay r = camera.ray((x + 0.5) * cam.width / 8.0, (y + 0.5) * cam.height / 8.0);
                if (!r.valid) continue;
                const Vec3& d = r.direction;
                raytrace::Hit h = embree.intersect(r.origin, d, 0.0, std::numeric_limits<double>::infinity());
                ++rays;
                if (!h.found) {
                    ++misses;
                    continue;
                }
                if (h.specular && !embree.specular(h.patch).glass && glm::dot(embree.specular(h.patch).normal, d) > 0)
                    ++mirrorBacks;
            }
        if (mirrorBacks >= rays / 2)
            out.push_back(
                fmt::format("/camera: the camera at {} looks at the back of a mirror ({} of {} view rays): "
                            "a mirror's back is black, so the image will be mostly black",
                            toString(cam.position), mirrorBacks, rays));
        if (misses == rays)
            out.push_back(fmt::format("/camera: the camera at {} sees no surface at all", toString(cam.position)));
    }
    if (checkSensors) {
        for (auto& line : sensorWarnings(scene, mesh, embree, prober, near, inSolid))
            if (!line.empty()) out.push_back(std::move(line));
        if (auto line = offSurfaceWarning(scene, mesh, embree)) out.push_back(std::move(*line));
    }
    for (const auto& m : scene.mirrors) {
        Vec3 c(0.0);
        for (const auto& x : m.polygon) c += x;
        c /= static_cast<double>(m.polygon.size());
        // Facing a surface closer than a quarter of its own size (a wall behind it) counts
        // as facing nothing; the size is √area, so a thin strip is not held to its length.
        const double size = std::sqrt(scene::polygonArea(m.polygon));
        Probe p = prober.probe(c, m.normal, 0.25 * size);
        if (p.fraction(p.backFaces + p.misses) >= kEnclosedFraction || p.fraction(p.nearHits) >= kEnclosedFraction)
            out.push_back(
                fmt::format("{}: the mirror at {} faces nothing it could reflect (its front sees the back of "
                            "surfaces, the void, or a surface within {:.3g} m): is it wound backwards?",
                            m.where, toString(c), 0.25 * size));
    }
    return out;
}

std::optional<std::string> insideSolid(const scene::Scene& scene, const radiosity::PatchMesh& mesh,
                                       const raytrace::EmbreeScene& embree, const Vec3& point) {
    const double diagonal = scene.diagonal();
    const Probe p = Prober(mesh, embree, diagonal).probe(point, Vec3(0.0), std::max(5e-3, 1e-4 * diagonal));
    if (p.fraction(p.backFaces) < kEnclosedFraction) return std::nullopt;
    return fmt::format("{} of {} rays from it hit the inside of surfaces", p.backFaces, p.rays);
}

std::optional<std::string> backLightWarning(const scene::Scene& scene, const radiosity::RadiositySolution& solution,
                                            double emittedFlux) {
    if (emittedFlux <= 0 || solution.backAbsorbedDirect < kBackLightShare * emittedFlux) return std::nullopt;
    const auto most = std::max_element(solution.backFlux.begin(), solution.backFlux.end());
    const auto& g = scene.groups[static_cast<size_t>(most - solution.backFlux.begin())];
    return fmt::format(
        "{:.3g} % of the direct light falls on the backs of one-sided surfaces and is absorbed there "
        "(most, {:.3g} %, on {}, material '{}'): a gap behind a surface, or a surface wound backwards? "
        "Close the gap, or make it \"two_sided\"",
        100 * solution.backAbsorbedDirect / emittedFlux, 100 * *most / emittedFlux, g.where,
        scene.materials[static_cast<size_t>(g.material)].name);
}

}  // namespace rayrad::app
