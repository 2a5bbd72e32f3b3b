#include <scene/sensor_parser.h>

#include <scene/observers.h>
#include <scene/polygon.h>

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace rayrad::scene {

using nlohmann::json;

namespace {

void parseReference(JsonObject r, SensorDesc& s) {
    s.refDirect = r.number("direct_lx");
    s.refIndirect = r.number("indirect_lx");
    s.refTotal = r.number("total_lx");
    r.finish();
}

}  // namespace

double standardGridSpacing(double d) { return std::min(10.0, 0.2 * std::pow(5.0, std::log10(std::max(d, 1e-3)))); }

SensorDesc parseSensor(JsonObject s, int index) {
    SensorDesc d;
    d.name = s.string("name").value_or("S" + std::to_string(index));
    s.required("position");
    d.position = s.vec3("position").value_or(Vec3(0.0));
    s.required("normal");
    d.normal = s.vec3("normal").value_or(Vec3(0, 0, 1));
    if (auto unit = unitDirection(d.normal)) d.normal = *unit;
    else s.error("normal", "the normal must not be zero");
    if (auto r = s.object("reference")) parseReference(*r, d);
    s.finish();
    return d;
}

void parseSensorGrid(JsonObject g, int index, std::vector<SensorDesc>& out) {
    std::string name = g.string("name").value_or("grid" + std::to_string(index));
    g.required("origin");
    g.required("u");
    g.required("v");
    Vec3 origin = g.vec3("origin").value_or(Vec3(0.0));
    Vec3 u = g.vec3("u").value_or(Vec3(1, 0, 0));
    Vec3 v = g.vec3("v").value_or(Vec3(0, 1, 0));
    int nu = 1, nv = 1;
    if (const json* c = g.array("counts")) {
        bool ok = c->size() == 2 && (*c)[0].is_number_integer() && (*c)[1].is_number_integer() &&
                  (*c)[0].get<long long>() >= 1 && (*c)[1].get<long long>() >= 1 &&
                  (*c)[0].get<long long>() * (*c)[1].get<long long>() <= 1'000'000;
        if (ok) nu = (*c)[0].get<int>(), nv = (*c)[1].get<int>();
        else g.error("counts", fmt::format("expected [nu, nv] with at most 10^6 points, got {}", describe(*c)));
    }
    Vec3 n = glm::cross(u, v);
    if (g.has("normal")) n = g.vec3("normal").value_or(n);
    if (auto unit = unitDirection(n)) {
        n = *unit;
    } else {
        g.error(g.has("normal") ? "normal" : "v", "the grid's normal is zero (u and v parallel?)");
        n = Vec3(0, 0, 1);
    }
    g.finish();
    // Points at the centres of the nu × nv cells of the parallelogram (origin, u, v).
    out.reserve(out.size() + static_cast<size_t>(nu) * nv);
    for (int j = 0; j < nv; ++j)
        for (int i = 0; i < nu; ++i) {
            SensorDesc s;
            s.name = fmt::format("{}[{},{}]", name, i, j);
            s.grid = name;
            s.gridU = i, s.gridV = j;
            s.position = origin + (i + 0.5) / nu * u + (j + 0.5) / nv * v;
            s.normal = n;
            out.push_back(s);
        }
}

/// A horizontal work plane: a room outline (x, z; y is up), a height, a border left out
/// along the walls, and a spacing (EN 12464-1's by default). Points at the centres of
/// equal cells over the outline's bounding box, kept where they lie inside the outline
/// and at least `border` from each of its edges.
void parseWorkPlane(JsonObject w, int index, std::vector<SensorDesc>& out) {
    const std::string name = w.string("name").value_or("workplane" + std::to_string(index));
    w.required("outline");
    std::vector<std::array<double, 2>> outline;
    if (const json* o = w.array("outline")) {
        for (const auto& p : *o) {
            if (!p.is_array() || p.size() != 2 || !p[0].is_number() || !p[1].is_number() ||
                !std::isfinite(p[0].get<double>()) || !std::isfinite(p[1].get<double>())) {
                w.error("outline", fmt::format("expected [[x, z], ...] (horizontal corners, y is up), got {}", describe(p)));
                return;
            }
            outline.push_back({p[0].get<double>(), p[1].get<double>()});
        }
    }
    const double height = w.number("height", 0.8);
    const double border = w.nonNegative("border", 0.5);
    double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
    for (const auto& p : outline)
        for (int a = 0; a < 2; ++a) lo[a] = std::min(lo[a], p[a]), hi[a] = std::max(hi[a], p[a]);
    std::vector<Vec3> polygon;
    for (const auto& p : outline) polygon.emplace_back(p[0], height, p[1]);
    if (outline.size() < 3 || polygonArea(polygon) <= 0) {
        w.error("outline", "expected at least three corners enclosing an area");
        return;
    }
    const double extent[2] = {hi[0] - lo[0] - 2 * border, hi[1] - lo[1] - 2 * border};
    if (!(extent[0] > 0 && extent[1] > 0)) {
        w.error("border", fmt::format("a border of {} m leaves nothing of the outline", border));
        return;
    }
    const double spacing = w.has("spacing") ? w.positive("spacing", 1.0) : standardGridSpacing(std::max(extent[0], extent[1]));
    w.finish();
    int n[2];
    for (int a = 0; a < 2; ++a) n[a] = std::max(1, static_cast<int>(std::ceil(extent[a] / spacing - 1e-9)));
    if (static_cast<long long>(n[0]) * n[1] > 1'000'000) {
        w.context().error(w.path(), fmt::format("the work plane would have {} × {} points, more than 10^6", n[0], n[1]));
        return;
    }
    const Vec3 up(0, 1, 0);
    auto distanceToOutline = [&](const Vec3& x) {
        double best = 1e300;
        for (size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++)
            best = std::min(best, segmentDistance(x, x, polygon[j], polygon[i]));
        return best;
    };
    size_t kept = 0;
    for (int j = 0; j < n[1]; ++j)
        for (int i = 0; i < n[0]; ++i) {
            const Vec3 x(lo[0] + border + (i + 0.5) / n[0] * extent[0], height, lo[1] + border + (j + 0.5) / n[1] * extent[1]);
            if (!polygonContains(polygon, up, x) || distanceToOutline(x) < border - 1e-9) continue;
            SensorDesc s;
            s.name = fmt::format("{}[{},{}]", name, i, j);
            s.grid = name;
            s.gridU = i, s.gridV = j;
            s.position = x;
            s.normal = up;
            out.push_back(s);
            ++kept;
        }
    if (kept == 0) w.context().error(w.path(), "no grid point lies inside the outline and its border");
}

SurfaceGridDesc parseSurfaceGrid(JsonObject g, int index) {
    SurfaceGridDesc d;
    d.where = g.path();
    d.name = g.string("name").value_or("surface" + std::to_string(index));
    g.required("material");
    d.material = g.string("material").value_or("");
    if (g.has("facing")) {
        d.facing = g.vec3("facing");
        if (d.facing) {
            if (auto unit = unitDirection(*d.facing)) d.facing = *unit;
            else g.error("facing", "the direction must not be zero");
        }
    }
    if (g.has("spacing")) d.spacing = g.positive("spacing", 1.0);
    d.offset = g.nonNegative("offset", 0.0);
    d.minArea = g.nonNegative("min_area", d.minArea);
    g.finish();
    return d;
}

Observer parseObserver(JsonObject o, int index) {
    Observer d;
    d.where = o.path();
    d.name = o.string("name").value_or("O" + std::to_string(index));
    o.required("position");
    d.position = o.vec3("position").value_or(Vec3(0.0));
    const auto direction = o.vec3("direction");
    const auto lookAt = o.vec3("look_at");
    if (direction && lookAt) o.error("look_at", "give \"direction\" or \"look_at\", not both");
    if (!direction && !lookAt) o.error("direction", "missing: where the observer looks (\"direction\" or \"look_at\")");
    const Vec3 sight = direction ? *direction : lookAt ? *lookAt - d.position : Vec3(0, 0, -1);
    if (auto unit = unitDirection(sight)) d.direction = *unit;
    else o.error(direction ? "direction" : "look_at", "the view direction has zero length");
    if (auto up = o.vec3("up")) {
        if (auto unit = unitDirection(*up)) d.up = *unit;
        else o.error("up", "up must not be zero");
    }
    if (std::abs(glm::dot(d.up, d.direction)) > 1 - 1e-9)
        o.error(o.has("up") ? "up" : "direction", "up must not be parallel to the view direction");
    if (auto limit = o.number("ugr_limit")) {
        if (!(*limit > 0) || !(*limit < 40))
            o.error("ugr_limit", fmt::format("expected a UGR between 0 and 40, got {:g}", *limit));
        d.ugrLimit = *limit;
    }
    if (auto task = o.string("task")) {
        d.task = *task;
        if (auto limit = ugrTaskLimit(*task)) {
            if (d.ugrLimit) o.error("task", "give \"ugr_limit\" or \"task\", not both");
            d.ugrLimit = limit;
        } else {
            o.error("task", fmt::format("unknown task \"{}\": one of {}", *task, ugrTaskNames()));
        }
    }
    o.finish();
    return d;
}

}  // namespace rayrad::scene
