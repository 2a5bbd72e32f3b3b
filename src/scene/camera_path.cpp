#include <scene/camera_path.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rayrad::scene {

namespace {

Vec3 viewDirection(const Camera& c) { return glm::normalize(c.lookAt - c.position); }

/// The motion from keyframe a to b: |Δposition| m + turn rad + |Δvfov| rad.
double motion(const Camera& a, const Camera& b) {
    const double cosTurn = std::clamp(glm::dot(viewDirection(a), viewDirection(b)), -1.0, 1.0);
    return glm::length(b.position - a.position) + std::acos(cosTurn) +
           std::abs(glm::radians(b.verticalFovDeg - a.verticalFovDeg));
}

/// Catmull–Rom tangent of a value at keyframe i (per unit of t), one-sided at the ends.
template <typename Get>
Vec3 tangent(const std::vector<Camera>& keys, const std::vector<double>& t, size_t i, Get get) {
    const size_t lo = i == 0 ? 0 : i - 1, hi = std::min(i + 1, keys.size() - 1);
    const double dt = t[hi] - t[lo];
    return dt > 0 ? (get(keys[hi]) - get(keys[lo])) / dt : Vec3(0.0);
}

/// Cubic Hermite between p0 (tangent m0) at s = 0 and p1 (m1) at s = 1; h is the
/// segment's length in t, which scales the tangents.
Vec3 hermite(const Vec3& p0, const Vec3& m0, const Vec3& p1, const Vec3& m1, double h, double s) {
    const double s2 = s * s, s3 = s2 * s;
    return (2 * s3 - 3 * s2 + 1) * p0 + (s3 - 2 * s2 + s) * h * m0 + (-2 * s3 + 3 * s2) * p1 + (s3 - s2) * h * m1;
}

}  // namespace

std::vector<Camera> framesAlongPath(const std::vector<Camera>& keys, int frames) {
    if (keys.size() < 2 || frames < 2) throw std::invalid_argument("a path needs at least 2 keyframes and 2 frames");
    std::vector<double> t(keys.size(), 0.0);
    for (size_t i = 1; i < keys.size(); ++i) t[i] = t[i - 1] + motion(keys[i - 1], keys[i]);
    const double total = t.back();
    if (!(total > 0)) throw std::invalid_argument("the keyframes do not move: every one has the same position, view and fov");
    const auto position = [](const Camera& c) { return c.position; };
    const auto lookAt = [](const Camera& c) { return c.lookAt; };

    std::vector<Camera> out;
    out.reserve(static_cast<size_t>(frames));
    size_t seg = 0;
    for (int k = 0; k < frames; ++k) {
        const double time = k == frames - 1 ? total : total * k / (frames - 1);
        while (seg + 2 < keys.size() && time > t[seg + 1]) ++seg;  // zero-length segments are passed over
        const double h = t[seg + 1] - t[seg];
        const double s = h > 0 ? std::clamp((time - t[seg]) / h, 0.0, 1.0) : 1.0;
        const Camera& a = keys[seg];
        const Camera& b = keys[seg + 1];
        Camera c = a;
        c.position = hermite(a.position, tangent(keys, t, seg, position), b.position, tangent(keys, t, seg + 1, position), h, s);
        c.lookAt = hermite(a.lookAt, tangent(keys, t, seg, lookAt), b.lookAt, tangent(keys, t, seg + 1, lookAt), h, s);
        const Vec3 up = (1 - s) * glm::normalize(a.up) + s * glm::normalize(b.up);
        c.up = glm::length(up) > 1e-6 ? glm::normalize(up) : b.up;
        c.verticalFovDeg = (1 - s) * a.verticalFovDeg + s * b.verticalFovDeg;
        const Vec3 forward = c.lookAt - c.position;
        if (!(glm::length(forward) > 1e-9) || glm::length(glm::cross(glm::normalize(forward), c.up)) < 1e-6)
            throw std::invalid_argument(fmt::format("frame {} looks at its own position or along its up vector: "
                                                    "move its look_at points further from the path",
                                                    k));
        out.push_back(c);
    }
    return out;
}

}  // namespace rayrad::scene
