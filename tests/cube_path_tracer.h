// An independent reference for the sensor gather on the paper's cube,
// shared by tests/real_scenes/sensor_accuracy_test.cpp and bench/sensor_accuracy.cpp.
// The cube [0, 10]³ is convex and closed, so a path tracer needs no visibility: from x,
// cosine-sampled directions hit the walls at y_1, y_2, … and
//   E_ind(x) = Σ_k ρ^k E_dir(y_k),   E_dir(y) = I cosθ / d²   (the cosine and π cancel),
// with the first bounce on Roberts' R2 sequence and the walk cut when ρ^k < 1e-7.
#pragma once

#include <core/math.h>
#include <core/random.h>

#include <fmt/format.h>

#include <cmath>
#include <cstdint>
#include <string>

namespace rayrad::test::cube {

constexpr double kSide = 10, kIntensity = 50000, kRho = 2.0 / 3.0;
inline const Vec3 kLight(5, 5, 5);

/// The scene: the cube facing inward, the point light at its centre, `sensors` (the body
/// of a JSON array), meshed at `maxEdge` metres (0.25: 19 200 triangles).
inline std::string scene(const std::string& sensors, double maxEdge) {
    return fmt::format(R"({{"materials": {{"wall": {{"reflectance": 0.6666666666666666}}}},
        "objects": [{{"type": "box", "material": "wall", "min": [0, 0, 0], "max": [10, 10, 10], "facing": "inward"}}],
        "lights": [{{"type": "point", "position": [5, 5, 5], "intensity_cd": 50000}}],
        "sensors": [{}], "radiosity": {{"max_edge": {}}}}})",
                       sensors, maxEdge);
}

/// Direct illuminance at wall point y, inward normal n (lx).
inline double directAt(const Vec3& y, const Vec3& n) {
    Vec3 d = kLight - y;
    double r2 = glm::dot(d, d);
    return kIntensity * glm::dot(n, d) / std::sqrt(r2) / r2;
}

/// The wall hit from x (inside) along unit w: point y and inward normal n.
inline void hitWall(const Vec3& x, const Vec3& w, Vec3& y, Vec3& n) {
    double best = 1e300, side = 0;
    int axis = 0;
    for (int a = 0; a < 3; ++a) {
        if (w[a] > 1e-15 && (kSide - x[a]) / w[a] < best) best = (kSide - x[a]) / w[a], axis = a, side = kSide;
        if (w[a] < -1e-15 && -x[a] / w[a] < best) best = -x[a] / w[a], axis = a, side = 0;
    }
    y = x + best * w;
    y[axis] = side;
    n = Vec3(0.0);
    n[axis] = side > 0 ? -1 : 1;
}

inline Vec3 cosineDirection(const Vec3& n, double u1, double u2) {
    Vec3 t = glm::normalize(glm::cross(n, std::abs(n.x) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0)));
    Vec3 b = glm::cross(n, t);
    double r = std::sqrt(u1), phi = 2 * kPi * u2;
    return glm::normalize(r * std::cos(phi) * t + r * std::sin(phi) * b + std::sqrt(std::max(0.0, 1 - u1)) * n);
}

/// E_ind(x) (lx) at wall point x0 with inward normal n0 by `paths` random walks;
/// `stream` (1, 2, …) selects an independent estimate.
inline double indirectReference(const Vec3& x0, const Vec3& n0, int paths, uint64_t stream) {
    const double g = 1.32471795724474602596;  // R2 sequence for the first bounce
    Random rng(stream, 11);
    double sum = 0;
    for (int p = 0; p < paths; ++p) {
        Vec3 x = x0, n = n0;
        double w = 1;
        for (int k = 0; w > 1e-7; ++k) {
            double u1 = k == 0 ? std::fmod(0.5 * stream + (p + 1) / g, 1.0) : rng.nextDouble();
            double u2 = k == 0 ? std::fmod(0.5 * stream + (p + 1) / (g * g), 1.0) : rng.nextDouble();
            Vec3 y, ny;
            hitWall(x, cosineDirection(n, u1, u2), y, ny);
            w *= kRho;
            sum += w * directAt(y, ny);
            x = y, n = ny;
        }
    }
    return sum / paths;
}

}  // namespace rayrad::test::cube
