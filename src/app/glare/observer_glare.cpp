#include <app/glare/observer_glare.h>

#include <app/pipeline.h>
#include <app/scene_warnings.h>
#include <app/sensor_table.h>
#include <core/input_error.h>
#include <radiosity/radiosity.h>
#include <scene/polygon.h>

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>

namespace rayrad::app {

namespace {

/// What a source adds, gathered over its parts: Σ ω_k, Σ ω_k / P_k² and Σ ω_k d_k.
struct SourceParts {
    double solidAngle = 0, weightedInversePSquared = 0;
    Vec3 direction{0.0};

    /// A part outside UGR's field of view (P > kMaxPositionIndex) does not count.
    void add(double omega, const Vec3& viewDirection) {
        const double p = positionIndex(viewDirection);
        if (p > kMaxPositionIndex) return;
        solidAngle += omega;
        weightedInversePSquared += omega / (p * p);
        direction += omega * viewDirection;
    }
    /// One source of luminance L whose L² ω / P² is the sum over its parts.
    GlareSource source(double luminance, const std::string& name) const {
        GlareSource s;
        s.luminance = luminance;
        s.solidAngle = solidAngle;
        s.positionIndex = std::sqrt(solidAngle / weightedInversePSquared);
        s.direction = glm::normalize(direction);
        s.name = name;
        return s;
    }
};

std::string lightPlace(const scene::PointLight& l, size_t i) {
    return l.where.empty() ? fmt::format("/lights/{}", i) : l.where;
}

/// A point light or luminaire as the eye sees it: its luminance toward the eye and the
/// solid angle of its luminous area, times the share of its opening the eye sees.
std::optional<GlareSource> lightSource(const scene::Scene& scene, const raytrace::EmbreeScene& embree,
                                       const scene::Observer& o, const ViewFrame& view, size_t index) {
    const scene::PointLight& light = scene.lights[index];
    const Vec3 toEye = o.position - light.position;
    const double r = glm::length(toEye);
    if (!(r > 0)) return std::nullopt;
    const Vec3 w = toEye / r;
    const Vec3 d = view.toView(-w);
    if (positionIndex(d) > kMaxPositionIndex) return std::nullopt;  // outside UGR's field of view
    const double intensity = luminance(light.intensityToward(w));
    if (!(intensity > 0)) return std::nullopt;
    const std::vector<Vec3> targets = light.openingPoints.empty() ? std::vector<Vec3>{light.position}
                                                                  : light.openingPoints;
    size_t seen = 0;
    for (const Vec3& t : targets) seen += embree.visible(o.position, t);
    if (seen == 0) return std::nullopt;
    const std::string place = lightPlace(light, index);
    if (!light.photometry)
        throw InputError(placeMessage(
            scene.file, o.where,
            fmt::format("observer \"{}\" sees the light {} ({}), which has no luminous area, so its luminance toward "
                        "the eye is unknown: make it a luminaire with a photometric file that gives its luminous "
                        "opening, or an area light",
                        o.name, place, light.isSpot ? "a spot" : "a point light")));
    const Vec3 c90 = glm::cross(-light.nadir, light.c0);
    const Vec3 local(glm::dot(w, light.c0), glm::dot(w, c90), glm::dot(w, light.nadir));
    const double area = projectedLuminousArea(*light.photometry, local);
    if (!(area > 0))
        throw InputError(placeMessage(
            scene.file, o.where,
            fmt::format("observer \"{}\" sees the luminaire {}, whose file {} gives no luminous area (width, "
                        "length and height 0), so its luminance toward the eye is unknown",
                        o.name, place, light.photometry->file)));
    GlareSource s;
    s.luminance = intensity / area;
    s.solidAngle = area / (r * r) * static_cast<double>(seen) / static_cast<double>(targets.size());
    s.direction = d;
    s.positionIndex = positionIndex(d);
    s.name = place;
    s.drawn = false;
    return s;
}

/// An area light's polygons as the eye sees them: each triangle cut into n² parts small
/// against their distance, each part's ω = A cos θ / r² if the eye sees it.
std::optional<GlareSource> areaLightSource(const scene::Scene& scene, const raytrace::EmbreeScene& embree,
                                           const scene::Observer& o, const ViewFrame& view,
                                           const scene::SurfaceGroup& g) {
    const scene::Material& m = scene.materials[static_cast<size_t>(g.material)];
    SourceParts parts;
    for (const auto& poly : g.polygons) {
        std::vector<Vec3> v;
        for (uint32_t k : poly) v.push_back(g.positions[k]);
        const Vec3 normal = scene::polygonNormal(v);
        for (size_t t = 1; t + 1 < v.size(); ++t) {
            const Vec3 a = v[0], b = v[t], c = v[t + 1];
            const double area = 0.5 * glm::length(glm::cross(b - a, c - a));
            if (!(area > 0)) continue;
            const double edge = std::max({glm::length(b - a), glm::length(c - b), glm::length(a - c)});
            const double distance = glm::length((a + b + c) / 3.0 - o.position);
            const int n = std::clamp(static_cast<int>(std::ceil(edge / (0.05 * std::max(distance, 1e-6)))), 1, 32);
            const double partArea = area / (n * n);
            auto addPart = [&](double s, double u) {
                const Vec3 x = a + s * (b - a) + u * (c - a);
                const Vec3 toPart = x - o.position;
                const double r2 = glm::dot(toPart, toPart);
                const Vec3 dir = toPart / std::sqrt(r2);
                const double cosEmitter = -glm::dot(dir, normal);  // emits from its front only
                const Vec3 d = view.toView(dir);
                if (cosEmitter <= 0 || d.z <= 0 || !embree.visible(o.position, x)) return;
                parts.add(partArea * cosEmitter / r2, d);
            };
            // The regular subdivision into n² triangles: their centroids.
            for (int i = 0; i < n; ++i)
                for (int j = 0; i + j < n; ++j) {
                    addPart((i + 1.0 / 3) / n, (j + 1.0 / 3) / n);
                    if (i + j + 1 < n) addPart((i + 2.0 / 3) / n, (j + 2.0 / 3) / n);
                }
        }
    }
    if (!(parts.solidAngle > 0)) return std::nullopt;
    return parts.source(luminance(m.emission), g.where + " (" + m.name + ")");
}

ObserverGlare glareAt(PipelineRun& run, const radiosity::Gatherer& gatherer, const scene::Observer& o) {
    const scene::Scene& scene = run.scene;
    if (auto why = insideSolid(scene, run.mesh, *run.embree, o.position))
        throw InputError(placeMessage(scene.file, o.where,
                                      fmt::format("observer \"{}\" at {} is inside a solid ({}): it sees nothing",
                                                  o.name, toString(o.position), *why)));
    ObserverGlare out;
    out.observer = o;
    const ViewFrame view = ViewFrame::from(o.direction, o.up);
    for (size_t i = 0; i < scene.lights.size(); ++i)
        if (auto s = lightSource(scene, *run.embree, o, view, i)) out.sources.push_back(*s);
    for (const auto& g : scene.groups)
        if (scene.materials[static_cast<size_t>(g.material)].isEmissive())
            if (auto s = areaLightSource(scene, *run.embree, o, view, g)) out.sources.push_back(*s);
    std::sort(out.sources.begin(), out.sources.end(),
              [](const GlareSource& a, const GlareSource& b) { return a.term() > b.term(); });

    // The illuminance at the eye on the plane facing the line of sight, as a sensor reads it.
    scene::Sensor eye;
    eye.name = o.name;
    eye.position = o.position;
    eye.normal = o.direction;
    const radiosity::SensorValue value = radiosity::evaluatePoint(scene, run.mesh, *run.embree, run.lighting, gatherer, eye);
    out.directVertical = luminance(value.direct);
    out.indirectVertical = luminance(value.indirect);
    out.backgroundLuminance = out.indirectVertical / kPi;
    out.ugr = unifiedGlareRating(out.backgroundLuminance, out.sources);
    if (out.sources.empty()) out.note = "no luminaire or area light in view";
    else if (!(out.backgroundLuminance > 0)) out.note = "no interreflected light at the eye (L_b = 0)";
    return out;
}

std::string limitText(const ObserverGlare& g) {
    return g.observer.ugrLimit ? fmt::format("{:g}", *g.observer.ugrLimit) : std::string();
}

std::string checkText(const ObserverGlare& g) {
    if (!g.observer.ugrLimit) return "";
    return g.passes() ? "pass" : "FAIL";
}

}  // namespace

double projectedLuminousArea(const scene::Photometry& p, const Vec3& w) {
    const double x = std::abs(w.x), y = std::abs(w.y), z = std::abs(w.z);
    double flat, sides;
    if (p.round) {
        flat = kPi * p.width * p.width / 4;
        sides = p.width * p.height * std::sqrt(std::max(0.0, 1 - w.z * w.z));
    } else {
        flat = p.width * p.length;
        sides = p.length * p.height * y + p.width * p.height * x;
    }
    return std::max(flat * z, kMinProjectedShare * flat) + sides;
}

std::vector<ObserverGlare> observerGlare(PipelineRun& run, bool pictures) {
    const scene::Scene& scene = run.scene;
    std::vector<ObserverGlare> out;
    if (scene.observers.empty()) return out;
    const radiosity::StageLog log{&run.report, nullptr, true, nullptr};
    const auto gatherer = radiosity::sensorGatherer(run.scene, run.mesh, *run.embree, run.lighting, log);
    run.report.begin(fmt::format("glare ({} observers)", scene.observers.size()));
    for (const auto& o : scene.observers) out.push_back(glareAt(run, *gatherer, o));
    if (!scene.daylight && !pictures) return out;
    // DGP: the sky, the sun and the area lights as the eye sees them, in a fisheye from the eye.
    PipelineOptions quiet;
    quiet.quiet = true;
    for (auto& g : out) {
        const scene::Observer& o = g.observer;
        scene::Camera eye;
        eye.position = o.position;
        eye.lookAt = o.position + o.direction;
        eye.up = o.up;
        eye.projection = scene::Projection::Fisheye;
        eye.width = eye.height = kObserverFisheyePixels;
        const RenderedView view = renderCamera(run, "fisheye of observer " + o.name, eye, quiet);
        const FisheyeGlare f = analyseFisheye(view.image, {}, "the fisheye of observer " + o.name);
        // The picture's sources, and the luminaires it does not draw.
        std::vector<GlareSource> undrawn, sources = f.sources;
        for (const auto& s : g.sources)
            if (!s.drawn) undrawn.push_back(s), sources.push_back(s);
        g.dgp = daylightGlareProbability(g.directVertical + g.indirectVertical, sources);
        g.dgpSources = sources.size();
        if (pictures) {
            FisheyeGlare shown = f;  // the figures the observer reports
            shown.dgp = *g.dgp;
            shown.ugr = g.ugr;
            shown.verticalIlluminance = g.directVertical + g.indirectVertical;
            g.marked = markGlareSources(view.image, shown, undrawn);
        }
    }
    return out;
}

std::string observerGlareTable(const std::vector<ObserverGlare>& observers) {
    const bool anyDgp = std::any_of(observers.begin(), observers.end(), [](const auto& g) { return g.dgp.has_value(); });
    std::string s = fmt::format("{:<20} {:>6} {:>6} {:>6} {:>8} {:>10} {:>10} {:>10}", "observer", "UGR", "limit",
                                "check", "sources", "L_b cd/m2", "Ev dir lx", "Ev ind lx");
    s += anyDgp ? fmt::format(" {:>6}  {}\n", "DGP", "class") : "\n";
    for (const auto& g : observers) {
        s += fmt::format("{:<20} {:>6} {:>6} {:>6} {:>8} {:>10.4g} {:>10.4g} {:>10.4g}", g.observer.name,
                         g.ugr ? fmt::format("{:.1f}", *g.ugr) : std::string("-"), limitText(g), checkText(g),
                         g.sources.size(), g.backgroundLuminance, g.directVertical, g.indirectVertical);
        if (g.dgp) s += fmt::format(" {:>6.3f}  {}", *g.dgp, dgpClass(*g.dgp));
        s += g.note.empty() ? "\n" : "  (" + g.note + ")\n";
        for (const auto& src : g.sources)
            s += fmt::format("    {:<40} L {:>10.4g} cd/m2  omega {:>9.3g} sr  P {:>5.2f}  L2w/P2 {:.4g}\n", src.name,
                             src.luminance, src.solidAngle, src.positionIndex, src.term());
    }
    return s;
}

std::string observerGlareCsv(const std::vector<ObserverGlare>& observers) {
    std::string s =
        "observer,x,y,z,dx,dy,dz,ugr,ugr_limit,task,check,background_cd_m2,ev_direct_lx,ev_indirect_lx,sources,dgp,"
        "dgp_class\n";
    for (const auto& g : observers) {
        const auto& o = g.observer;
        s += fmt::format("{},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{},{},{},{},{:.6g},{:.6g},{:.6g},{},{},{}\n",
                         csvField(o.name), o.position.x, o.position.y, o.position.z, o.direction.x, o.direction.y,
                         o.direction.z, g.ugr ? fmt::format("{:.2f}", *g.ugr) : std::string(), limitText(g),
                         csvField(o.task), checkText(g), g.backgroundLuminance, g.directVertical, g.indirectVertical,
                         g.sources.size(), g.dgp ? fmt::format("{:.4f}", *g.dgp) : std::string(),
                         g.dgp ? dgpClass(*g.dgp) : std::string());
    }
    return s;
}

nlohmann::json observerGlareJson(const std::vector<ObserverGlare>& observers) {
    using nlohmann::json;
    json out = json::array();
    auto vec = [](const Vec3& v) { return json::array({v.x, v.y, v.z}); };
    for (const auto& g : observers) {
        const auto& o = g.observer;
        json e = {{"name", o.name},
                  {"position", vec(o.position)},
                  {"direction", vec(o.direction)},
                  {"ugr", g.ugr ? json(*g.ugr) : json(nullptr)},
                  {"passes", g.passes()},
                  {"background_cd_m2", g.backgroundLuminance},
                  {"ev_direct_lx", g.directVertical},
                  {"ev_indirect_lx", g.indirectVertical},
                  {"sources", json::array()}};
        if (o.ugrLimit) e["ugr_limit"] = *o.ugrLimit;
        if (!o.task.empty()) e["task"] = o.task;
        if (!g.note.empty()) e["note"] = g.note;
        if (g.dgp) {
            e["dgp"] = *g.dgp;
            e["dgp_class"] = dgpClass(*g.dgp);
            e["dgp_sources"] = g.dgpSources;
        }
        for (const auto& s : g.sources)
            e["sources"].push_back({{"name", s.name},
                                    {"luminance_cd_m2", s.luminance},
                                    {"solid_angle_sr", s.solidAngle},
                                    {"position_index", s.positionIndex}});
        out.push_back(std::move(e));
    }
    return out;
}

std::string observerGlarePath(const std::string& sensorCsvPath) {
    const std::filesystem::path p(sensorCsvPath);
    return (p.parent_path() / (p.stem().string() + ".glare" + p.extension().string())).string();
}

std::string glarePicturePath(const std::string& dir, const std::vector<scene::Observer>& observers, size_t i) {
    auto clean = [](const std::string& name) {
        std::string out = name.empty() ? "observer" : name;
        for (char& c : out)
            if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '-' && c != '_') c = '_';
        return out;
    };
    std::string name = clean(observers[i].name);
    for (size_t k = 0; k < observers.size(); ++k)
        if (k != i && clean(observers[k].name) == name) {
            name += fmt::format("-{}", i);
            break;
        }
    return (std::filesystem::path(dir) / (name + ".png")).string();
}

}  // namespace rayrad::app
