// A pinhole camera: pixel coordinates → world-space rays.
#pragma once

#include <core/math.h>
#include <scene/scene.h>

namespace rayrad::raytrace {

class PinholeCamera {
  public:
    explicit PinholeCamera(const scene::Camera& camera);
    /// Unit direction through image position (px, py) in pixels, (0, 0) the top-left
    /// corner of the image, y down.
    Vec3 direction(double px, double py) const;
    const Vec3& position() const { return m_position; }
    int width() const { return m_width; }
    int height() const { return m_height; }

  private:
    Vec3 m_position, m_forward, m_right, m_up;
    double m_tanHalfFov;
    int m_width, m_height;
};

}  // namespace rayrad::raytrace
