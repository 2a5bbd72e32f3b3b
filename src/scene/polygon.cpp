#include <scene/polygon.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace rayrad::scene {

static Vec3 newell(const std::vector<Vec3>& v) {
    Vec3 n(0.0);
    for (size_t i = 0; i < v.size(); ++i) {
        const Vec3& a = v[i];
        const Vec3& b = v[(i + 1) % v.size()];
        n += Vec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
    }
    return n;  // length = 2 × area
}

Vec3 polygonNormal(const std::vector<Vec3>& v) {
    Vec3 n = newell(v);
    double len = glm::length(n);
    return len > 0 ? n / len : Vec3(0.0);
}

double polygonArea(const std::vector<Vec3>& v) { return 0.5 * glm::length(newell(v)); }

double polygonArea(const std::vector<Vec3>& positions, const std::vector<uint32_t>& indices) {
    std::vector<Vec3> v;
    for (uint32_t i : indices) v.push_back(positions[i]);
    return polygonArea(v);
}

double maxPlaneDistance(const std::vector<Vec3>& v) {
    Vec3 n = polygonNormal(v);
    Vec3 c(0.0);
    for (const auto& p : v) c += p;
    c /= static_cast<double>(v.size());
    double d = 0;
    for (const auto& p : v) d = std::max(d, std::abs(glm::dot(p - c, n)));
    return d;
}

bool isConvexAround(const std::vector<Vec3>& v, const Vec3& normal) {
    for (size_t i = 0; i < v.size(); ++i) {
        const Vec3& a = v[i];
        const Vec3& b = v[(i + 1) % v.size()];
        const Vec3& c = v[(i + 2) % v.size()];
        if (glm::dot(glm::cross(b - a, c - b), normal) < 0) return false;
    }
    return true;
}

std::vector<std::array<uint32_t, 3>> triangulate(const std::vector<Vec3>& v) {
    Vec3 n = polygonNormal(v);
    std::vector<uint32_t> idx;
    for (uint32_t i = 0; i < v.size(); ++i) idx.push_back(i);
    std::vector<std::array<uint32_t, 3>> out;
    auto inside = [&](const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
        return glm::dot(glm::cross(b - a, p - a), n) >= 0 && glm::dot(glm::cross(c - b, p - b), n) >= 0 &&
               glm::dot(glm::cross(a - c, p - c), n) >= 0;
    };
    size_t guard = 0;
    while (idx.size() > 3 && guard++ < 10 * v.size() * v.size()) {
        bool clipped = false;
        for (size_t i = 0; i < idx.size(); ++i) {
            uint32_t ia = idx[(i + idx.size() - 1) % idx.size()], ib = idx[i], ic = idx[(i + 1) % idx.size()];
            const Vec3 &a = v[ia], &b = v[ib], &c = v[ic];
            if (glm::dot(glm::cross(b - a, c - b), n) <= 0) continue;  // reflex corner
            bool ear = true;
            for (uint32_t j : idx)
                if (j != ia && j != ib && j != ic && inside(v[j], a, b, c)) ear = false;
            if (!ear) continue;
            out.push_back({ia, ib, ic});
            idx.erase(idx.begin() + static_cast<long>(i));
            clipped = true;
            break;
        }
        if (!clipped) break;  // not simple: fall back to a fan for what is left
    }
    for (size_t i = 1; i + 1 < idx.size(); ++i) out.push_back({idx[0], idx[i], idx[i + 1]});
    return out;
}

bool polygonContains(const std::vector<Vec3>& v, const Vec3& normal, const Vec3& p) {
    Vec3 a = glm::abs(normal);
    int drop = a.x > a.y ? (a.x > a.z ? 0 : 2) : (a.y > a.z ? 1 : 2);
    int u = (drop + 1) % 3, w = (drop + 2) % 3;
    bool inside = false;
    for (size_t i = 0, j = v.size() - 1; i < v.size(); j = i++) {
        double ui = v[i][u], wi = v[i][w], uj = v[j][u], wj = v[j][w];
        if ((wi > p[w]) != (wj > p[w]) && p[u] < (uj - ui) * (p[w] - wi) / (wj - wi) + ui) inside = !inside;
    }
    return inside;
}

double segmentDistance(const Vec3& p, const Vec3& q, const Vec3& r, const Vec3& s) {
    // Closest points p + t d1, r + u d2 with t, u in [0, 1] (Ericson, Real-Time Collision
    // Detection, 5.1.9): minimise over t for the best u, clamping each in turn.
    const Vec3 d1 = q - p, d2 = s - r, w = p - r;
    const double a = glm::dot(d1, d1), e = glm::dot(d2, d2), f = glm::dot(d2, w);
    double t = 0, u = 0;
    if (a <= 0 && e <= 0) return glm::length(w);
    if (a <= 0) {
        u = std::clamp(f / e, 0.0, 1.0);
    } else {
        const double c = glm::dot(d1, w);
        if (e <= 0) {
            t = std::clamp(-c / a, 0.0, 1.0);
        } else {
            const double b = glm::dot(d1, d2), denom = a * e - b * b;
            t = denom > 0 ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
            u = (b * t + f) / e;
            if (u < 0) u = 0, t = std::clamp(-c / a, 0.0, 1.0);
            else if (u > 1) u = 1, t = std::clamp((b - c) / a, 0.0, 1.0);
        }
    }
    return glm::length((p + t * d1) - (r + u * d2));
}

double segmentPolygonDistance(const Vec3& a, const Vec3& b, const std::vector<Vec3>& v, const Vec3& normal) {
    const double da = glm::dot(normal, a - v[0]), db = glm::dot(normal, b - v[0]);
    if ((da <= 0) != (db <= 0) || da == 0) {
        const Vec3 crossing = da == db ? a : a + (da / (da - db)) * (b - a);
        if (polygonContains(v, normal, crossing)) return 0;
    }
    double best = std::numeric_limits<double>::infinity();
    for (const auto& [end, d] : {std::pair{a, da}, std::pair{b, db}})
        if (polygonContains(v, normal, end - d * normal)) best = std::min(best, std::abs(d));  // over the face
    for (size_t i = 0, j = v.size() - 1; i < v.size(); j = i++) best = std::min(best, segmentDistance(a, b, v[j], v[i]));
    return best;
}

bool trianglesInOnePlane(const std::vector<Vec3>& positions, const std::vector<std::vector<uint32_t>>& triangles) {
    if (triangles.empty()) return false;
    Vec3 lo(1e300), hi(-1e300);
    for (const auto& t : triangles)
        for (uint32_t i : t) lo = glm::min(lo, positions[i]), hi = glm::max(hi, positions[i]);
    const double tolerance = 1e-6 * glm::length(hi - lo);
    std::optional<Vec3> normal;
    Vec3 origin(0.0);
    for (const auto& t : triangles) {
        const auto n = unitDirection(glm::cross(positions[t[1]] - positions[t[0]], positions[t[2]] - positions[t[0]]));
        if (!n) continue;  // degenerate: no side of its own
        if (!normal) normal = n, origin = positions[t[0]];
        if (glm::dot(*n, *normal) < std::cos(kPi / 180)) return false;
        for (uint32_t i : t)
            if (std::abs(glm::dot(*normal, positions[i] - origin)) > tolerance) return false;
    }
    return normal.has_value();
}

}  // namespace rayrad::scene
