#include <raytrace/camera.h>

#include <cmath>

namespace rayrad::raytrace {

PinholeCamera::PinholeCamera(const scene::Camera& c)
    : m_position(c.position),
      m_forward(glm::normalize(c.lookAt - c.position)),
      m_tanHalfFov(std::tan(glm::radians(c.verticalFovDeg) / 2)),
      m_width(c.width),
      m_height(c.height) {
    m_right = glm::normalize(glm::cross(m_forward, c.up));
    m_up = glm::cross(m_right, m_forward);
}

Vec3 PinholeCamera::direction(double px, double py) const {
    double aspect = static_cast<double>(m_width) / m_height;
    double sx = (2 * px / m_width - 1) * m_tanHalfFov * aspect;
    double sy = (1 - 2 * py / m_height) * m_tanHalfFov;
    return glm::normalize(m_forward + sx * m_right + sy * m_up);
}

}  // namespace rayrad::raytrace
