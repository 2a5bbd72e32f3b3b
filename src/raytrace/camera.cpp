#include <raytrace/camera.h>

#include <algorithm>
#include <cmath>

namespace rayrad::raytrace {

ImageCamera::ImageCamera(const scene::Camera& c)
    : m_projection(c.projection),
      m_position(c.position),
      m_forward(glm::normalize(c.lookAt - c.position)),
      m_tanHalfFov(std::tan(glm::radians(c.verticalFovDeg) / 2)),
      m_orthoHeight(c.orthoHeight),
      m_width(c.width),
      m_height(c.height) {
    m_right = glm::normalize(glm::cross(m_forward, c.up));
    m_up = glm::cross(m_right, m_forward);
}

CameraRay ImageCamera::ray(double px, double py) const {
    const double aspect = static_cast<double>(m_width) / m_height;
    // Image-plane coordinates: x to the right, y up, both from −1 to 1 across the height.
    const double sx = (2 * px / m_width - 1) * aspect, sy = 1 - 2 * py / m_height;
    switch (m_projection) {
    case scene::Projection::Perspective:
        return {m_position, glm::normalize(m_forward + sx * m_tanHalfFov * m_right + sy * m_tanHalfFov * m_up), true};
    case scene::Projection::Orthographic:
        return {m_position + 0.5 * m_orthoHeight * (sx * m_right + sy * m_up), m_forward, true};
    case scene::Projection::Fisheye: {
        // Equidistant: θ = (r / R) · 90°, R the radius of the largest circle in the image.
        const double R = std::min(m_width, m_height) / 2.0;
        const double u = px - m_width / 2.0, v = m_height / 2.0 - py;
        const double r = std::hypot(u, v) / R;
        if (r > 1) return {m_position, m_forward, false};
        const double theta = r * kPi / 2, phi = std::atan2(v, u);
        return {m_position,
                std::cos(theta) * m_forward + std::sin(theta) * (std::cos(phi) * m_right + std::sin(phi) * m_up), true};
    }
    }
    return {m_position, m_forward, false};
}

RayCone ImageCamera::pixelCone() const {
    switch (m_projection) {
    case scene::Projection::Perspective: return {0.0, 2 * m_tanHalfFov / m_height};
    case scene::Projection::Orthographic: return {m_orthoHeight / m_height, 0.0};
    case scene::Projection::Fisheye: return {0.0, (kPi / 2) / (std::min(m_width, m_height) / 2.0)};
    }
    return {};
}

}  // namespace rayrad::raytrace
