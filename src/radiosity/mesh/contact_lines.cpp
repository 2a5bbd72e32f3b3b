#include <radiosity/mesh/contact_lines.h>

#include <algorithm>
#include <cmath>

namespace rayrad::radiosity {

bool ContactLine::covers(double x, double tol) const {
    for (const auto& r : covered)
        if (x >= r[0] - tol && x <= r[1] + tol) return true;
    return false;
}

std::vector<std::array<Vec3, 2>> groupBounds(const scene::Scene& scene) {
    std::vector<std::array<Vec3, 2>> out;
    for (const auto& g : scene.groups) {
        Vec3 lo(1e300), hi(-1e300);
        for (const auto& p : g.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
        out.push_back({lo, hi});
    }
    return out;
}

namespace {

bool overlap(const std::array<Vec3, 2>& a, const std::array<Vec3, 2>& b, double tol) {
    for (int k = 0; k < 3; ++k)
        if (a[0][k] > b[1][k] + tol || b[0][k] > a[1][k] + tol) return false;
    return true;
}

/// Adds a touching range at parameter `at` to the lines, merging lines within `tol`.
void addLine(std::vector<ContactLine>& lines, double at, double from, double to, double tol) {
    for (auto& l : lines)
        if (std::abs(l.at - at) <= tol) {
            l.covered.push_back({from, to});
            return;
        }
    lines.push_back({at, {{from, to}}});
}

}  // namespace

QuadContacts findContacts(const scene::Scene& scene, size_t group, const std::vector<Vec3>& q,
                          const std::vector<std::array<Vec3, 2>>& bounds, double tolerance) {
    QuadContacts out;
    const Vec3 u = q[1] - q[0], v = q[3] - q[0];
    const double lu = glm::length(u), lv = glm::length(v);
    if (lu <= 0 || lv <= 0) return out;
    if (glm::length(q[2] - (q[0] + u + v)) > tolerance) return out;  // not a parallelogram
    const Vec3 n = glm::normalize(glm::cross(u, v));
    const double offset = glm::dot(n, q[0]);
    // Parameters (s, t) of a point in the quad's plane: [u·u u·v; u·v v·v] (s, t) = (u·w, v·w).
    const double uu = glm::dot(u, u), uv = glm::dot(u, v), vv = glm::dot(v, v), det = uu * vv - uv * uv;
    if (det <= 0) return out;
    auto param = [&](const Vec3& p) {
        Vec3 w = p - q[0];
        double a = glm::dot(u, w), b = glm::dot(v, w);
        return std::array<double, 2>{(vv * a - uv * b) / det, (uu * b - uv * a) / det};
    };
    std::array<Vec3, 2> box{glm::min(glm::min(q[0], q[1]), glm::min(q[2], q[3])),
                            glm::max(glm::max(q[0], q[1]), glm::max(q[2], q[3]))};
    const double ts = tolerance / lu, tt = tolerance / lv;  // the tolerance in parameter units

    std::vector<Vec3> points;
    for (size_t gi = 0; gi < scene.groups.size(); ++gi) {
        if (gi == group || !overlap(box, bounds[gi], tolerance)) continue;
        const scene::SurfaceGroup& g = scene.groups[gi];
        const scene::SurfaceKind kind = scene.materials[g.material].kind;
        if (kind == scene::SurfaceKind::Glass || kind == scene::SurfaceKind::Opening) continue;
        for (const auto& poly : g.polygons) {
            // Signed distances to the quad's plane; a surface must reach into its front.
            double dmax = -1e300, dmin = 1e300;
            for (uint32_t i : poly) {
                double d = glm::dot(n, g.positions[i]) - offset;
                dmax = std::max(dmax, d), dmin = std::min(dmin, d);
            }
            if (dmax <= tolerance || dmin > tolerance) continue;  // behind, in the plane, or clear of it
            points.clear();
            for (size_t k = 0; k < poly.size(); ++k) {
                const Vec3& a = g.positions[poly[k]];
                const Vec3& b = g.positions[poly[(k + 1) % poly.size()]];
                double da = glm::dot(n, a) - offset, db = glm::dot(n, b) - offset;
                if (std::abs(da) <= tolerance) points.push_back(a);
                if ((da > tolerance && db < -tolerance) || (da < -tolerance && db > tolerance))
                    points.push_back(a + (b - a) * (da / (da - db)));
            }
            if (points.size() < 2) continue;
            // The segment between the two points farthest apart, in quad parameters.
            size_t ia = 0, ib = 1;
            double best = -1;
            for (size_t i = 0; i < points.size(); ++i)
                for (size_t j = i + 1; j < points.size(); ++j) {
                    double d = glm::length(points[i] - points[j]);
                    if (d > best) best = d, ia = i, ib = j;
                }
            if (best <= tolerance) continue;  // touches at a point only
            auto a = param(points[ia]), b = param(points[ib]);
            double ds = std::abs(b[0] - a[0]) * lu, dt = std::abs(b[1] - a[1]) * lv;  // metres
            if (dt <= tolerance) {                                                    // along s: a line t = const
                double t = 0.5 * (a[1] + b[1]);
                double from = std::max(0.0, std::min(a[0], b[0])), to = std::min(1.0, std::max(a[0], b[0]));
                if (t > tt && t < 1 - tt && to - from > ts) addLine(out.constT, t, from, to, tt);
            } else if (ds <= tolerance) {  // along t: a line s = const
                double s = 0.5 * (a[0] + b[0]);
                double from = std::max(0.0, std::min(a[1], b[1])), to = std::min(1.0, std::max(a[1], b[1]));
                if (s > ts && s < 1 - ts && to - from > tt) addLine(out.constS, s, from, to, ts);
            }
        }
    }
    auto byAt = [](const ContactLine& x, const ContactLine& y) { return x.at < y.at; };
    std::sort(out.constS.begin(), out.constS.end(), byAt);
    std::sort(out.constT.begin(), out.constT.end(), byAt);
    return out;
}

}  // namespace rayrad::radiosity
