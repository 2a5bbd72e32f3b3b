#include <scene/scene_parser.h>

#include <core/colour_temperature.h>
#include <core/input_error.h>
#include <core/input_file.h>
#include <scene/daylight/daylight_parser.h>
#include <scene/file_views.h>
#include <scene/json_reader.h>
#include <scene/overrides.h>
#include <scene/sensor_names.h>
#include <scene/sensor_parser.h>

#include <fmt/format.h>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <filesystem>
#include <map>

namespace rayrad::scene {

using nlohmann::json;

namespace {

// ---- pieces ----------------------------------------------------------------------

/// "group": the light group an emitter belongs to (a name; "" when not given).
std::string lightGroupOf(JsonObject& o) {
    if (!o.has("group")) return "";
    const std::string g = o.string("group").value_or("");
    if (g.empty()) o.error("group", "a light group needs a name");
    return g;
}

/// "texture": "FILE" or {"file": "FILE", "repeat": [u, v]} (an image read by OpenImageIO;
/// relative to the scene's directory).
void parseTexture(JsonObject& m, MaterialDesc& d, const std::string& sceneDir) {
    const json* given = m.peek("texture");
    if (given && given->is_string()) {
        d.texture = m.string("texture").value_or("");
    } else if (auto t = m.object("texture")) {
        t->required("file");
        d.texture = t->string("file").value_or("");
        if (const json* r = t->array("repeat")) {
            if (r->size() == 2 && (*r)[0].is_number() && (*r)[1].is_number() && (*r)[0].get<double>() > 0 &&
                (*r)[1].get<double>() > 0)
                d.textureRepeat = {(*r)[0].get<double>(), (*r)[1].get<double>()};
            else
                t->error("repeat", fmt::format("expected [u, v], each a positive number, got {}", describe(*r)));
        }
        t->finish();
    }
    if (d.texture.empty()) {
        m.error("texture", "expected an image file name, or {\"file\": ..., \"repeat\": [u, v]}");
        return;
    }
    const std::filesystem::path f(d.texture);
    d.resolvedTexture = f.is_absolute() ? f.string() : (std::filesystem::path(sceneDir) / f).string();
}

/// The largest diffuse reflectance a scene may give: above any real surface (Spectralon
/// reflects 0.99), and where the interreflections already multiply the light by 1 000. Nearer
/// 1 the shooting cannot converge (1 − 10⁻¹⁶ made NaN), so it is refused.
constexpr double kMaxReflectance = 0.999;

MaterialDesc parseMaterial(JsonObject m, const std::string& name, const std::string& sceneDir) {
    MaterialDesc d;
    d.name = name;
    d.where = m.path();
    std::string type = m.string("type").value_or("diffuse");
    static const std::vector<std::string> kTypes = {"diffuse", "emissive", "mirror", "glass", "opening"};
    if (std::find(kTypes.begin(), kTypes.end(), type) == kTypes.end()) {
        std::string hint = closestMatch(type, kTypes);
        m.error("type", fmt::format("unknown material type \"{}\" ({})", type,
                                    hint.empty() ? "expected diffuse, emissive, mirror, glass or opening"
                                                 : fmt::format("did you mean \"{}\"?", hint)));
    }
    if (type == "opening") {
        // A window or skylight: daylight enters through it, from behind its front side.
        d.kind = SurfaceKind::Opening;
        if (m.has("transmittance")) {
            d.transmittance = m.number("transmittance", 1.0);
            if (!(d.transmittance > 0 && d.transmittance <= 1))
                m.error("transmittance",
                        fmt::format("a glazing's normal transmittance lies in (0, 1] (1: no glazing), got {}",
                                    d.transmittance));
        }
        m.finish();
        return d;
    }
    if (type == "mirror") {
        d.kind = SurfaceKind::Mirror;
        m.required("specular_reflectance");
        d.specular = m.rgb("specular_reflectance", 0.0, 1.0, /*hiInclusive=*/true).value_or(Rgb(1.0));
        m.finish();
        return d;
    }
    if (type == "glass") {
        d.kind = SurfaceKind::Glass;
        d.ior = m.number("ior", 1.5);
        if (!(d.ior >= 1.0 && d.ior <= 4.0))
            m.error("ior", fmt::format("expected an index of refraction in [1, 4], got {}", d.ior));
        m.finish();
        return d;
    }
    if (type == "diffuse" && m.has("texture")) {
        // With a texture, the reflectance is the texture's multiplier (default 1).
        parseTexture(m, d, sceneDir);
        d.reflectance = m.rgb("reflectance", 0.0, 1.0, /*hiInclusive=*/true).value_or(Rgb(1.0));
    } else {
        d.reflectance = m.rgb("reflectance", 0.0, kMaxReflectance, /*hiInclusive=*/true).value_or(Rgb(0.0));
    }
    if (type == "diffuse") {
        d.twoSided = m.boolean("two_sided").value_or(false);
        d.backReflectance = m.rgb("back_reflectance", 0.0, kMaxReflectance, /*hiInclusive=*/true);
        if (d.backReflectance && !d.twoSided)
            m.error("back_reflectance", "a back reflectance needs \"two_sided\": true");
    }
    if (type == "emissive") {
        d.emissive = true;
        d.color = m.rgb("color", 0.0, 1e30, true).value_or(Rgb(1.0));
        if (luminance(d.color) <= 0) m.error("color", "emission colour must have a positive luminance");
        bool hasL = m.has("luminance_cd_m2"), hasF = m.has("flux_lm");
        if (hasL == hasF)
            m.error("luminance_cd_m2", "an emissive material needs exactly one of \"luminance_cd_m2\" or \"flux_lm\"");
        if (hasL) d.luminance = m.positive("luminance_cd_m2", 0.0);
        if (hasF) d.flux = m.positive("flux_lm", 0.0);
        d.lightGroup = lightGroupOf(m);
    }
    m.finish();
    return d;
}

glm::dmat4 parseTransform(JsonObject t) {
    glm::dmat4 m(1.0);
    if (const json* rows = t.array("matrix")) {
        bool ok = rows->size() == 16;
        for (size_t i = 0; ok && i < 16; ++i) ok = (*rows)[i].is_number() && std::isfinite((*rows)[i].get<double>());
        if (!ok) {
            t.error("matrix", "expected 16 finite numbers, row by row");
        } else {
            for (int r = 0; r < 4; ++r)
                for (int c = 0; c < 4; ++c) m[c][r] = (*rows)[r * 4 + c].get<double>();  // glm is column-major
        }
    }
    // Applied to points in the order scale, rotate, translate.
    Vec3 translate = t.vec3("translate").value_or(Vec3(0.0));
    Vec3 scale(1.0);
    if (t.has("scale")) {
        if (auto s = t.rgb("scale", -1e30, 1e30, true)) scale = *s;
        if (scale.x == 0 || scale.y == 0 || scale.z == 0) t.error("scale", "a scale of zero flattens the object");
    }
    Vec3 axis = t.vec3("rotate_axis").value_or(Vec3(0, 0, 1));
    double angle = t.number("rotate_deg", 0.0);
    if (auto unit = unitDirection(axis)) {
        axis = *unit;
    } else {
        t.error("rotate_axis", "the rotation axis must not be zero");
        axis = Vec3(0, 0, 1);
    }
    glm::dmat4 trs = glm::translate(glm::dmat4(1.0), translate) *
                     glm::rotate(glm::dmat4(1.0), glm::radians(angle), glm::normalize(axis)) *
                     glm::scale(glm::dmat4(1.0), scale);
    t.finish();
    const glm::dmat4 total = trs * m;
    const double det = glm::determinant(glm::dmat3(total));
    if (!(std::abs(det) > 1e-12) && t.context().errors == 0)
        t.context().error(t.path(),
                          fmt::format("the transform is singular (determinant {:.3g}): it flattens the object", det));
    return total;
}

bool parseFacing(JsonObject& o, bool defaultInward) {
    auto f = o.string("facing");
    if (!f) return defaultInward;
    if (*f == "inward") return true;
    if (*f == "outward") return false;
    o.error("facing", fmt::format("expected \"inward\" or \"outward\", got \"{}\"", *f));
    return defaultInward;
}

/// "keep_above": [[nx, ny, nz, offset], ...]: keep triangles with n·x ≥ offset.
std::vector<std::pair<Vec3, double>> parseKeepAbove(JsonObject& o) {
    std::vector<std::pair<Vec3, double>> planes;
    const json* a = o.array("keep_above");
    if (!a) return planes;
    for (size_t i = 0; i < a->size(); ++i) {
        const json& p = (*a)[i];
        bool ok = p.is_array() && p.size() == 4;
        for (size_t k = 0; ok && k < 4; ++k) ok = p[k].is_number() && std::isfinite(p[k].get<double>());
        Vec3 n = ok ? Vec3(p[0].get<double>(), p[1].get<double>(), p[2].get<double>()) : Vec3(0.0);
        if (!ok || glm::length(n) == 0) {
            o.error("keep_above", fmt::format("entry {}: expected [nx, ny, nz, offset] with a non-zero normal", i));
            continue;
        }
        double len = glm::length(n);
        planes.emplace_back(n / len, p[3].get<double>() / len);
    }
    return planes;
}

ObjectDesc parseObject(JsonObject o, const std::map<std::string, int>& materials, const std::string& sceneDir) {
    ObjectDesc d;
    d.where = o.path();
    o.required("type");
    std::string type = o.string("type").value_or("");
    static const std::vector<std::string> kTypes = {"quad", "polygon", "box", "sphere", "mesh"};
    if (type == "quad")
        d.kind = ObjectKind::Quad;
    else if (type == "polygon")
        d.kind = ObjectKind::Polygon;
    else if (type == "box")
        d.kind = ObjectKind::Box;
    else if (type == "sphere")
        d.kind = ObjectKind::Sphere;
    else if (type == "mesh")
        d.kind = ObjectKind::Mesh;
    else if (!type.empty()) {
        std::string hint = closestMatch(type, kTypes);
        o.error("type", fmt::format("unknown object type \"{}\"{}", type,
                                    hint.empty() ? " (expected quad, polygon, box, sphere or mesh)"
                                                 : fmt::format(" (did you mean \"{}\"?)", hint)));
    }

    if (d.kind != ObjectKind::Mesh) o.required("material");  // a mesh may take its file's materials
    d.material = o.string("material").value_or("");
    if (!d.material.empty() && !materials.count(d.material)) {
        std::vector<std::string> names;
        for (const auto& [n, i] : materials) names.push_back(n);
        std::string hint = closestMatch(d.material, names);
        o.error("material", fmt::format("unknown material \"{}\"{}", d.material,
                                        hint.empty() ? "" : fmt::format(" (did you mean \"{}\"?)", hint)));
    }

    switch (d.kind) {
        case ObjectKind::Quad:
        case ObjectKind::Polygon: {
            o.required("vertices");
            d.vertices = o.points("vertices");
            if (o.has("vertices") && d.kind == ObjectKind::Quad && d.vertices.size() != 4 && !d.vertices.empty())
                o.error("vertices", fmt::format("a quad needs 4 vertices, got {}", d.vertices.size()));
            if (o.has("vertices") && d.kind == ObjectKind::Polygon && d.vertices.size() < 3)
                o.error("vertices", fmt::format("a polygon needs at least 3 vertices, got {}", d.vertices.size()));
            break;
        }
        case ObjectKind::Box: {
            o.required("min");
            o.required("max");
            d.boxMin = o.vec3("min").value_or(Vec3(0.0));
            d.boxMax = o.vec3("max").value_or(Vec3(1.0));
            for (int i = 0; i < 3; ++i)
                if (o.has("min") && o.has("max") && !(d.boxMax[i] > d.boxMin[i]))
                    o.error("max", "every coordinate of \"max\" must exceed \"min\"");
            d.inward = parseFacing(o, false);
            break;
        }
        case ObjectKind::Sphere: {
            d.center = o.vec3("center").value_or(Vec3(0.0));
            d.radius = o.positive("radius", 1.0);
            d.subdivisions = o.integer("subdivisions", 8, 1, 512);
            d.inward = parseFacing(o, false);
            d.keepAbove = parseKeepAbove(o);
            break;
        }
        case ObjectKind::Mesh: {
            o.required("file");
            d.file = o.string("file").value_or("");
            std::filesystem::path p(d.file);
            d.resolvedFile = p.is_absolute() ? p.string() : (std::filesystem::path(sceneDir) / p).string();
            d.keepAbove = parseKeepAbove(o);
            if (auto units = o.string("units")) {
                static const std::map<std::string, double> kUnits = {
                    {"m", 1.0}, {"cm", 0.01}, {"mm", 0.001}, {"in", 0.0254}, {"ft", 0.3048}};
                auto it = kUnits.find(*units);
                if (it == kUnits.end())
                    o.error("units", "expected \"m\", \"cm\", \"mm\", \"in\" or \"ft\", got \"" + *units + "\"");
                else
                    d.fileUnit = it->second;
            }
            break;
        }
    }
    if (auto t = o.object("transform")) d.transform = parseTransform(*t);
    // The file's unit first, then the transform (whose translation is in metres).
    if (d.fileUnit > 0) d.transform = d.transform * glm::scale(glm::dmat4(1.0), Vec3(d.fileUnit));
    o.finish();
    return d;
}

/// A luminaire aimed: "aim" (a point) or "nadir" (a direction), and "c0_toward".
void parseLuminaireAim(JsonObject& l, LightDesc& d) {
    if (l.has("aim") && l.has("nadir"))
        l.error("nadir", "give either \"aim\" (a point) or \"nadir\" (a direction), not both");
    Vec3 nadir = l.has("aim") ? l.vec3("aim").value_or(d.position - Vec3(0, 1, 0)) - d.position
                              : l.vec3("nadir").value_or(Vec3(0, -1, 0));
    if (auto unit = unitDirection(nadir)) {
        d.nadir = *unit;
    } else {
        l.error(l.has("aim") ? "aim" : "nadir",
                "the luminaire's axis must not be zero (aim at a point other than its position)");
        d.nadir = Vec3(0, -1, 0);
    }
    // C0: the given direction with its part along the axis removed.
    const Vec3 toward = l.vec3("c0_toward").value_or(std::abs(d.nadir.x) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 0, 1));
    const Vec3 c0 = toward - glm::dot(toward, d.nadir) * d.nadir;
    if (glm::length(c0) < 1e-9 * std::max(1.0, glm::length(toward))) {
        l.error("c0_toward", "the C0 direction must not be parallel to the luminaire's axis");
        d.c0 = std::abs(d.nadir.x) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 0, 1);
    } else {
        d.c0 = glm::normalize(c0);
    }
}

/// A luminaire turned as DIALux turns one: "rotation_deg": [x, y, z], rotations in degrees
/// about the scene's x, y and z axes, applied in that order to the luminaire at rest
/// (pointing down, −y, with C0 along +x). Right-handed: positive turns counter-clockwise
/// seen from the axis' positive end.
void parseLuminaireRotation(JsonObject& l, LightDesc& d) {
    for (const char* key : {"aim", "nadir", "c0_toward"})
        if (l.has(key)) l.error(key, fmt::format("give either \"rotation_deg\" or \"{}\", not both", key));
    const Vec3 angles = l.vec3("rotation_deg").value_or(Vec3(0.0));
    glm::dmat4 r(1.0);
    r = glm::rotate(glm::dmat4(1.0), glm::radians(angles.x), Vec3(1, 0, 0)) * r;
    r = glm::rotate(glm::dmat4(1.0), glm::radians(angles.y), Vec3(0, 1, 0)) * r;
    r = glm::rotate(glm::dmat4(1.0), glm::radians(angles.z), Vec3(0, 0, 1)) * r;
    d.nadir = glm::normalize(Vec3(glm::dmat3(r) * Vec3(0, -1, 0)));
    d.c0 = glm::normalize(Vec3(glm::dmat3(r) * Vec3(1, 0, 0)));
}

/// A luminaire: a photometric file at a position, aimed; its flux, dimming, maintenance
/// and colour (RGB or a colour temperature).
void parseLuminaire(JsonObject& l, LightDesc& d, const std::string& sceneDir) {
    l.required("file");
    d.file = l.string("file").value_or("");
    const std::filesystem::path f(d.file);
    d.resolvedFile = f.is_absolute() ? f.string() : (std::filesystem::path(sceneDir) / f).string();
    if (l.has("rotation_deg")) {
        parseLuminaireRotation(l, d);
    } else {
        parseLuminaireAim(l, d);
    }
    if (l.has("flux_lm")) d.fluxLm = l.positive("flux_lm", 1.0);
    d.dimming = l.number("dimming", 1.0);
    if (!(d.dimming > 0 && d.dimming <= 1))
        l.error("dimming", fmt::format("expected a factor in (0, 1], got {}", d.dimming));
    d.maintenance = l.number("maintenance_factor", 1.0);
    if (!(d.maintenance > 0 && d.maintenance <= 1))
        l.error("maintenance_factor", fmt::format("expected a factor in (0, 1], got {}", d.maintenance));
    d.pointSource = l.boolean("point_source").value_or(false);
    if (l.has("color") && l.has("cct_k")) l.error("cct_k", "give either \"color\" or \"cct_k\", not both");
    if (l.has("cct_k")) {
        const double k = l.number("cct_k", 4000.0);
        if (!(k >= kMinColourTemperature && k <= kMaxColourTemperature))
            l.error("cct_k", fmt::format("expected a colour temperature from {:g} to {:g} K, got {}",
                                         kMinColourTemperature, kMaxColourTemperature, k));
        else
            d.color = colourOfTemperature(k);
    }
}

LightDesc parseLight(JsonObject l, const std::string& sceneDir) {
    LightDesc d;
    d.where = l.path();
    d.lightGroup = lightGroupOf(l);
    l.required("type");
    std::string type = l.string("type").value_or("point");
    if (type == "point")
        d.kind = LightKind::Point;
    else if (type == "spot")
        d.kind = LightKind::Spot;
    else if (type == "luminaire")
        d.kind = LightKind::Luminaire;
    else
        l.error("type", fmt::format("unknown light type \"{}\" (expected \"point\", \"spot\" or \"luminaire\")", type));
    l.required("position");
    d.position = l.vec3("position").value_or(Vec3(0.0));
    if (d.kind != LightKind::Luminaire) {
        l.required("intensity_cd");
        d.intensity = l.positive("intensity_cd", 1.0);
    }
    Rgb c = l.rgb("color", 0.0, 1e30, true).value_or(Rgb(1.0));
    if (luminance(c) <= 0)
        l.error("color", "light colour must have a positive luminance");
    else
        d.color = c / luminance(c);
    if (d.kind == LightKind::Luminaire) parseLuminaire(l, d, sceneDir);
    if (d.kind == LightKind::Spot) {
        if (l.has("look_at") && l.has("direction"))
            l.error("direction", "give either \"direction\" or \"look_at\", not both");
        if (l.has("look_at")) {
            Vec3 target = l.vec3("look_at").value_or(d.position + Vec3(0, 0, -1));
            d.direction = target - d.position;
        } else {
            d.direction = l.vec3("direction").value_or(Vec3(0, 0, -1));
        }
        if (auto unit = unitDirection(d.direction)) {
            d.direction = *unit;
        } else {
            l.error(l.has("look_at") ? "look_at" : "direction", "the spot direction must not be zero");
            d.direction = Vec3(0, 0, -1);
        }
        d.innerAngleDeg = l.number("inner_angle_deg", 30.0);
        d.outerAngleDeg = l.number("outer_angle_deg", 45.0);
        if (!(d.outerAngleDeg > 0 && d.outerAngleDeg <= 180))
            l.error("outer_angle_deg", fmt::format("expected an angle in (0, 180], got {}", d.outerAngleDeg));
        if (!(d.innerAngleDeg >= 0 && d.innerAngleDeg <= d.outerAngleDeg))
            l.error("inner_angle_deg", "expected an angle from 0 to outer_angle_deg");
    }
    l.finish();
    return d;
}

/// "resolution": [width, height], each from 1 to 16384, at most 10⁸ pixels.
void readResolution(JsonObject& c, CameraDesc& d) {
    if (const json* r = c.array("resolution")) {
        bool ok = r->size() == 2 && (*r)[0].is_number_integer() && (*r)[1].is_number_integer();
        if (ok) {
            long long w = (*r)[0].get<long long>(), h = (*r)[1].get<long long>();
            if (w < 1 || h < 1 || w > 16384 || h > 16384)
                ok = false;
            else if (w * h > 100'000'000LL)
                c.error("resolution", fmt::format("{} × {} is {} pixels, more than the 100 000 000 an image may have "
                                                  "(render --tile spreads a big image over processes, but the "
                                                  "whole is held to merge it)",
                                                  w, h, w * h));
            else
                d.width = static_cast<int>(w), d.height = static_cast<int>(h);
        }
        if (!ok)
            c.error("resolution", fmt::format("expected [width, height], each from 1 to 16384, got {}", describe(*r)));
    }
}

/// look_at away from position, up neither zero nor along the viewing direction; up is
/// made a unit vector (a denormal one would overflow when the camera normalises it).
void checkViewingDirection(JsonObject& c, CameraDesc& d) {
    const std::optional<Vec3> forward = unitDirection(d.lookAt - d.position);
    const std::optional<Vec3> up = unitDirection(d.up);
    if (!forward)
        c.error("look_at", "look_at must differ from position");
    else if (!up)
        c.error("up", "up must not be zero");
    else if (glm::length(glm::cross(*forward, *up)) < 1e-9)
        c.error("up", "up must not be parallel to the viewing direction");
    else
        d.up = *up;
}

CameraDesc parseCamera(JsonObject c) {
    CameraDesc d;
    d.where = c.path();
    if (auto p = c.string("projection")) {
        if (*p == "perspective")
            d.projection = Projection::Perspective;
        else if (*p == "fisheye")
            d.projection = Projection::Fisheye;
        else if (*p == "orthographic")
            d.projection = Projection::Orthographic;
        else
            c.error("projection", "expected \"perspective\", \"fisheye\" or \"orthographic\", got \"" + *p + "\"");
    }
    if (d.projection == Projection::Orthographic) {
        c.required("height_m");
        d.orthoHeight = c.positive("height_m", 1.0);
    }
    d.fromSensor = c.string("from_sensor").value_or("");
    if (d.fromSensor.empty()) {
        c.required("position");
        c.required("look_at");
    } else {
        for (const char* key : {"position", "look_at", "up"})
            if (c.has(key)) c.error(key, std::string("give either \"from_sensor\" or \"") + key + "\", not both");
    }
    d.position = c.vec3("position").value_or(d.position);
    d.lookAt = c.vec3("look_at").value_or(d.position + Vec3(0, 0, -1));
    d.up = c.vec3("up").value_or(Vec3(0, 1, 0));
    d.verticalFovDeg = c.number("vfov_deg", 45.0);
    if (!(d.verticalFovDeg > 0 && d.verticalFovDeg < 180))
        c.error("vfov_deg", fmt::format("expected an angle in (0, 180), got {}", d.verticalFovDeg));
    readResolution(c, d);
    checkViewingDirection(c, d);
    c.finish();
    return d;
}

/// "camera_path": keyframes (position, look_at, up, vfov_deg) and the frame count; the
/// path's resolution and field of view are every keyframe's unless one sets its own fov.
CameraPathDesc parseCameraPath(JsonObject o) {
    CameraPathDesc path;
    path.where = o.path();
    o.required("frames");
    o.required("keyframes");
    path.frames = o.integer("frames", 2, 2, kMaxPathFrames);
    CameraDesc common;
    common.verticalFovDeg = o.number("vfov_deg", 45.0);
    if (!(common.verticalFovDeg > 0 && common.verticalFovDeg < 180))
        o.error("vfov_deg", fmt::format("expected an angle in (0, 180), got {}", common.verticalFovDeg));
    readResolution(o, common);
    if (const json* keys = o.array("keyframes")) {
        for (size_t i = 0; i < keys->size(); ++i) {
            const std::string where = o.childPath("keyframes") + "/" + std::to_string(i);
            if (!(*keys)[i].is_object()) {
                o.context().error(where, "expected an object, got " + describe((*keys)[i]));
                continue;
            }
            JsonObject k((*keys)[i], where, o.context());
            CameraDesc d = common;
            d.where = where;
            k.required("position");
            k.required("look_at");
            d.position = k.vec3("position").value_or(d.position);
            d.lookAt = k.vec3("look_at").value_or(d.position + Vec3(0, 0, -1));
            d.up = k.vec3("up").value_or(Vec3(0, 1, 0));
            d.verticalFovDeg = k.number("vfov_deg", common.verticalFovDeg);
            if (!(d.verticalFovDeg > 0 && d.verticalFovDeg < 180))
                k.error("vfov_deg", fmt::format("expected an angle in (0, 180), got {}", d.verticalFovDeg));
            checkViewingDirection(k, d);
            k.finish();
            path.keyframes.push_back(d);
        }
        if (keys->size() < 2)
            o.error("keyframes", fmt::format("a path needs at least 2 keyframes, got {}", keys->size()));
    }
    o.finish();
    return path;
}

void parseRadiosity(JsonObject r, SceneDesc& d) {
    d.meshing.premesh = r.boolean("premesh").value_or(d.meshing.premesh);
    d.meshing.maxEdge = r.nonNegative("max_edge", d.meshing.maxEdge);
    d.meshing.trianglesPerSurface = r.integer("triangles_per_surface", d.meshing.trianglesPerSurface, 0, 10'000'000);
    d.meshing.maxCellAspect = r.number("max_cell_aspect", d.meshing.maxCellAspect);
    if (d.meshing.maxCellAspect < 1) r.error("max_cell_aspect", "expected a number >= 1");
    d.meshing.creaseAngleDeg = r.number("crease_angle_deg", d.meshing.creaseAngleDeg);
    if (!(d.meshing.creaseAngleDeg >= 0 && d.meshing.creaseAngleDeg < 180))
        r.error("crease_angle_deg",
                fmt::format("expected an angle in [0, 180) (0: vertices as the file shares them), got {}",
                            d.meshing.creaseAngleDeg));
    d.meshing.maxPatches = r.positive("max_patches", d.meshing.maxPatches);
    d.shooting.stopUnshot = r.number("stop_unshot", d.shooting.stopUnshot);
    if (!(d.shooting.stopUnshot > 0 && d.shooting.stopUnshot < 1))
        r.error("stop_unshot", "expected a number in (0, 1)");
    d.shooting.maxShots = static_cast<int64_t>(r.nonNegative("max_shots", static_cast<double>(d.shooting.maxShots)));
    d.shooting.maxSeconds = r.nonNegative("max_seconds", d.shooting.maxSeconds);
    d.formFactors.analyticDistance = r.nonNegative("analytic_distance", d.formFactors.analyticDistance);
    d.direct.areaLightSamples = r.integer("area_light_samples", d.direct.areaLightSamples, 1, 4096);
    d.gather.gatherLevels = r.integer("gather_levels", d.gather.gatherLevels, 0, 64);
    d.gather.gatherRefineLevels = r.integer("gather_refine_levels", d.gather.gatherRefineLevels, 0, 8);
    d.gather.gatherRefineTolerance = r.nonNegative("gather_refine_tolerance", d.gather.gatherRefineTolerance);
    d.gather.gatherFarDiameters = r.nonNegative("gather_far_diameters", d.gather.gatherFarDiameters);
    if (d.gather.gatherFarDiameters > 0 && d.gather.gatherFarDiameters < 2)
        r.error("gather_far_diameters",
                "expected 0 (every patch on its own) or at least 2 (nearer, a point sits "
                "inside the node it would take as one source)");
    d.shooting.shootFarDiameters = r.nonNegative("shoot_far_diameters", d.shooting.shootFarDiameters);
    if (d.shooting.shootFarDiameters > 0 && d.shooting.shootFarDiameters < 2)
        r.error("shoot_far_diameters",
                "expected 0 (every member on its own) or at least 2 (nearer, a receiver sits "
                "inside the node it would take as one source)");
    d.gather.gatherMinWeight = r.number("gather_min_weight", d.gather.gatherMinWeight);
    if (!(d.gather.gatherMinWeight >= 0 && d.gather.gatherMinWeight < 1))
        r.error("gather_min_weight", "expected a number in [0, 1)");
    d.reconstruction.edgeGatherLevels = r.integer("edge_gather_levels", d.reconstruction.edgeGatherLevels, 0, 64);
    d.reconstruction.seamProfileNodes = r.integer("seam_profile_nodes", d.reconstruction.seamProfileNodes, 0,
                                                  ReconstructionOptions::kMaxSeamProfileNodes);
    d.shooting.oneChannelWhenGrey = r.boolean("one_channel_when_grey").value_or(d.shooting.oneChannelWhenGrey);
    d.shooting.conserveEnergy = r.boolean("conserve_energy").value_or(d.shooting.conserveEnergy);
    d.shooting.overshoot = r.boolean("overshoot").value_or(d.shooting.overshoot);
    if (auto mode = r.string("mirrors")) {
        if (*mode == "image")
            d.mirrorImages.mirrors = MirrorImageOptions::Mode::Image;
        else if (*mode == "ignore")
            d.mirrorImages.mirrors = MirrorImageOptions::Mode::Ignore;
        else
            r.error("mirrors", fmt::format("expected \"image\" or \"ignore\", got \"{}\"", *mode));
    }
    d.mirrorImages.mirrorDepth = r.integer("mirror_depth", d.mirrorImages.mirrorDepth, 1, 64);
    d.mirrorImages.mirrorMinWeight = r.number("mirror_min_weight", d.mirrorImages.mirrorMinWeight);
    if (!(d.mirrorImages.mirrorMinWeight > 0 && d.mirrorImages.mirrorMinWeight < 1))
        r.error("mirror_min_weight", "expected a number in (0, 1)");
    d.mirrorImages.mirrorMinShare = r.number("mirror_min_share", d.mirrorImages.mirrorMinShare);
    if (!(d.mirrorImages.mirrorMinShare >= 0 && d.mirrorImages.mirrorMinShare < 1))
        r.error("mirror_min_share", "expected a number in [0, 1)");
    if (auto rec = r.string("reconstruction")) {
        if (*rec == "linear")
            d.reconstruction.reconstruction = ReconstructionOptions::Mode::Linear;
        else if (*rec == "average")
            d.reconstruction.reconstruction = ReconstructionOptions::Mode::Average;
        else
            r.error("reconstruction", fmt::format("expected \"linear\" or \"average\", got \"{}\"", *rec));
    }
    r.finish();
}

void parseClusters(JsonObject c, SceneDesc& d) {
    ClusterOptions& o = d.clusters;
    o.enabled = c.boolean("enabled").value_or(o.enabled);
    o.voxelSize = c.nonNegative("voxel_size", o.voxelSize);
    o.patchesPerCluster = c.nonNegative("patches_per_cluster", o.patchesPerCluster);
    o.sizePercent = c.positive("size_percent", o.sizePercent);
    o.referenceArea = c.nonNegative("reference_area", o.referenceArea);
    o.maxVoxelCrowding = c.nonNegative("max_voxel_crowding", o.maxVoxelCrowding);
    o.normalToleranceDeg = c.number("normal_tolerance_deg", o.normalToleranceDeg);
    if (!(o.normalToleranceDeg >= 0 && o.normalToleranceDeg <= 180))
        c.error("normal_tolerance_deg", "expected an angle from 0 to 180");
    o.maxIlluminanceStep = c.nonNegative("max_illuminance_step_lx", o.maxIlluminanceStep);
    o.energyCorrection = c.boolean("energy_correction").value_or(o.energyCorrection);
    if (auto detail = c.string("receiver_detail")) {
        if (*detail == "patch")
            o.receiverDetail = true;
        else if (*detail == "cluster")
            o.receiverDetail = false;
        else
            c.error("receiver_detail", fmt::format("expected \"patch\" or \"cluster\", got \"{}\"", *detail));
    }
    o.pushPullFraction = c.number("push_pull_fraction", o.pushPullFraction);
    if (!(o.pushPullFraction > 0 && o.pushPullFraction <= 1))
        c.error("push_pull_fraction", "expected a number in (0, 1]");
    c.finish();
}

void parseRender(JsonObject r, SceneDesc& d) {
    d.render.samplesPerPixel = r.integer("spp", d.render.samplesPerPixel, 1, 65536);
    d.render.seed = static_cast<uint64_t>(r.integer("seed", static_cast<int>(d.render.seed), 0, 2147483647));
    d.render.areaLightSamples = r.integer("area_light_samples", d.render.areaLightSamples, 1, 4096);
    d.render.directThreshold = r.number("direct_threshold", d.render.directThreshold);
    if (!(d.render.directThreshold >= 0 && d.render.directThreshold < 1))
        r.error("direct_threshold", "expected a number in [0, 1) (0: every light shadow-tested)");
    d.render.shareFarShadows = r.boolean("share_far_shadows").value_or(d.render.shareFarShadows);
    d.render.sensorAreaLightSamples =
        r.integer("sensor_area_light_samples", d.render.sensorAreaLightSamples, 1, 1 << 20);
    d.render.maxDepth = r.integer("max_depth", d.render.maxDepth, 0, 64);
    d.render.displayRangeCompression =
        r.boolean("display_range_compression").value_or(d.render.displayRangeCompression);
    d.render.smoothingAngleDeg = r.number("smoothing_angle_deg", d.render.smoothingAngleDeg);
    if (!(d.render.smoothingAngleDeg >= 0 && d.render.smoothingAngleDeg < 90))
        r.error("smoothing_angle_deg",
                fmt::format("expected an angle in [0, 90) (0: flat shading), got {}", d.render.smoothingAngleDeg));
    if (auto indirect = r.string("indirect")) {
        if (*indirect == "mesh")
            d.render.gatherIndirect = false;
        else if (*indirect == "gather")
            d.render.gatherIndirect = true;
        else
            r.error("indirect", fmt::format("expected \"mesh\" or \"gather\", got \"{}\"", *indirect));
    }
    r.finish();
}

std::string lineColumn(const std::string& text, size_t byte) {
    size_t line = 1, column = 1;
    for (size_t i = 0; i < byte && i < text.size(); ++i) {
        if (text[i] == '\n')
            ++line, column = 1;
        else
            ++column;
    }
    return fmt::format("line {}, column {}", line, column);
}

/// The scene file's text as a JSON object without duplicate keys; false (and an error
/// naming the line and column) when it is not one.
bool readJsonObject(const std::string& text, ParseContext& ctx, json& root) {
    if (const size_t at = tooDeepAt(text); at != std::string::npos) {
        ctx.error(lineColumn(text, at), fmt::format("arrays and objects nested more than {} levels deep (a scene "
                                                    "needs about six)", kMaxJsonDepth));
        return false;
    }
    try {
        root = json::parse(text);
    } catch (const json::parse_error& e) {
        // nlohmann's message starts with "[json.exception.parse_error.101] parse error at line ..."
        std::string what = e.what();
        auto colon = what.find(": ", what.find("parse error"));
        ctx.error(lineColumn(text, e.byte > 0 ? e.byte - 1 : 0),
                  "invalid JSON: " + (colon == std::string::npos ? what : what.substr(colon + 2)));
        return false;
    } catch (const json::exception& e) {
        // e.g. out_of_range.406 "number overflow parsing '1e999'": no byte offset is given,
        // so find the quoted token in the text to name the place.
        std::string what = e.what();
        auto q1 = what.find('\''), q2 = what.rfind('\'');
        std::string place = "/";
        if (q1 != std::string::npos && q2 > q1) {
            auto at = text.find(what.substr(q1 + 1, q2 - q1 - 1));
            if (at != std::string::npos) place = lineColumn(text, at);
        }
        auto bracket = what.find("] ");
        ctx.error(place, "invalid JSON: " + (bracket == std::string::npos ? what : what.substr(bracket + 2)));
        return false;
    }
    if (!root.is_object()) {
        ctx.error("/", "the scene must be a JSON object, got " + describe(root));
        return false;
    }
    if (std::string duplicate = findDuplicateKey(text); !duplicate.empty()) {
        const auto colon = duplicate.find(": ", duplicate.find("column"));
        ctx.error(duplicate.substr(0, colon), duplicate.substr(colon + 2));
        return false;
    }
    return true;
}

}  // namespace

SceneDesc parseScene(const std::string& text, const std::string& fileName, const std::vector<Override>& overrides,
                     const ErrorHandler& onError) {
    ParseContext ctx;
    ctx.onError = onError ? onError : [&](const std::string& place, const std::string& message) {
        throw InputError(placeMessage(sourceOf(place, overrides, fileName), place, message));
    };
    SceneDesc desc;
    desc.file = fileName;

    json root;
    if (!readJsonObject(text, ctx, root)) return desc;
    for (const auto& o : overrides) applyOverride(root, o, ctx);

    std::string sceneDir = std::filesystem::path(fileName).parent_path().string();
    JsonObject top(root, "", ctx);
    top.string("description");
    top.string("provenance");
    // Unknown top-level keys first: a misspelt "Materials" explains the errors it causes.
    top.finish({"materials", "objects", "lights", "camera", "cameras", "sensors", "sensor_grids", "work_planes",
                "surface_grids", "camera_path", "radiosity", "clusters", "render", "daylight", "observers"});

    std::map<std::string, int> materialIndex;
    if (auto mats = top.object("materials")) {
        const json& mj = root["materials"];
        for (auto it = mj.begin(); it != mj.end(); ++it) {
            if (!it.value().is_object()) {
                mats->error(it.key(), "expected an object, got " + describe(it.value()));
                continue;
            }
            if (it.key().find('\0') != std::string::npos) {
                std::string shown;  // the place, printable
                for (char c : it.key()) shown += c == '\0' ? std::string("\\u0000") : std::string(1, c);
                mats->error(shown, "the material's name holds a NUL character");
                continue;
            }
            materialIndex[it.key()] = static_cast<int>(desc.materials.size());
            desc.materials.push_back(
                parseMaterial(JsonObject(it.value(), mats->childPath(it.key()), ctx), it.key(), sceneDir));
        }
        mats->finish([&] {
            std::set<std::string> all;
            for (auto it = mj.begin(); it != mj.end(); ++it) all.insert(it.key());
            return all;
        }());
    }
    auto eachObject = [&](const char* key, auto&& fn) {
        if (const json* arr = top.array(key)) {
            for (size_t i = 0; i < arr->size(); ++i) {
                std::string path = top.childPath(key) + "/" + std::to_string(i);
                if (!(*arr)[i].is_object()) {
                    ctx.error(path, "expected an object, got " + describe((*arr)[i]));
                    continue;
                }
                fn(JsonObject((*arr)[i], path, ctx), static_cast<int>(i));
            }
        }
    };
    eachObject("objects", [&](JsonObject o, int) { desc.objects.push_back(parseObject(o, materialIndex, sceneDir)); });
    eachObject("lights", [&](JsonObject o, int) { desc.lights.push_back(parseLight(o, sceneDir)); });
    if (auto c = top.object("camera")) {
        desc.camera = parseCamera(*c);
        desc.views.emplace_back("camera", *desc.camera);
    }
    eachObject("cameras", [&](JsonObject o, int) {
        o.required("name");
        const std::string name = o.string("name").value_or("");
        const std::string where = o.path();
        CameraDesc c = parseCamera(o);
        if (name == "all") ctx.error(where + "/name", "\"all\" is reserved (render --camera all renders every view)");
        for (const auto& [other, unused] : desc.views)
            if (other == name) ctx.error(where + "/name", "the view name \"" + name + "\" is used twice");
        if (!desc.camera) desc.camera = c;
        desc.views.emplace_back(name, c);
    });
    if (auto p = top.object("camera_path")) desc.cameraPath = parseCameraPath(*p);
    eachObject("sensors", [&](JsonObject o, int i) { desc.sensors.push_back(parseSensor(o, i)); });
    eachObject("sensor_grids", [&](JsonObject o, int i) { parseSensorGrid(o, i, desc.sensors); });
    eachObject("work_planes", [&](JsonObject o, int i) { parseWorkPlane(o, i, desc.sensors); });
    eachObject("surface_grids", [&](JsonObject o, int i) { desc.surfaceGrids.push_back(parseSurfaceGrid(o, i)); });
    eachObject("observers", [&](JsonObject o, int i) { desc.observers.push_back(parseObserver(o, i)); });
    if (auto r = top.object("radiosity")) parseRadiosity(*r, desc);
    if (auto c = top.object("clusters")) parseClusters(*c, desc);
    if (auto r = top.object("render")) parseRender(*r, desc);
    if (auto d = top.object("daylight")) desc.daylight = parseDaylight(*d);

    if (ctx.errors == 0 && desc.objects.empty()) ctx.error("/objects", "the scene has no geometry");
    if (ctx.errors == 0 && desc.lights.empty() && !desc.daylight) {
        bool anyEmitter = false;
        for (const auto& m : desc.materials) anyEmitter |= m.emissive;
        // A mesh that takes its file's materials may bring emitters or lights (checked
        // again when the scene is built).
        for (const auto& o : desc.objects) anyEmitter |= o.kind == ObjectKind::Mesh && o.material.empty();
        if (!anyEmitter) ctx.error("/lights", "the scene has no light: add a light or an emissive material");
    }
    for (size_t i : sensorsNamedAgain(desc.sensors))
        ctx.error("/sensors", fmt::format("sensor name \"{}\" is used twice", desc.sensors[i].name));
    return desc;
}

SceneDesc loadScene(const std::string& fileName, const std::vector<Override>& overrides) {
    if (fileName == "-") {
        // Standard input can be read once; a run that loads the scene twice (the command
        // checks it before the work, the pipeline builds it) gets the same text.
        static const std::string text = readInputFile("-", "scene file", kMaxSceneFileBytes);
        SceneDesc desc = parseScene(text, kStandardInputName, overrides);
        addFileViews(desc);
        return desc;
    }
    SceneDesc desc = parseScene(readInputFile(fileName, "scene file", kMaxSceneFileBytes), fileName, overrides);
    addFileViews(desc);
    return desc;
}

}  // namespace rayrad::scene
