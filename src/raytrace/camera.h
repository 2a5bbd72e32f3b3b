// A camera: pixel coordinates → world-space rays, for the three projections
// (perspective, equidistant fisheye, orthographic).
#pragma once

#include <core/math.h>
#include <raytrace/ray_cone.h>
#include <scene/scene.h>

namespace rayrad::raytrace {

struct CameraRay {
    Vec3 origin{0.0};
    Vec3 direction{0, 0, -1};  ///< unit
    bool valid = true;         ///< false outside a fisheye's circle: the pixel stays black
};

class ImageCamera {
  public:
    explicit ImageCamera(const scene::Camera& camera);
    /// The ray through image position (px, py) in pixels, (0, 0) the top-left corner of
    /// the image, y down.
    CameraRay ray(double px, double py) const;
    /// The cone of one pixel: perspective γ = 2 tan(fov/2) / height (its angle at the image
    /// centre), fisheye γ = 90° / R, orthographic w0 = the view height / height and γ = 0.
    RayCone pixelCone() const;
    int width() const { return m_width; }
    int height() const { return m_height; }

  private:
    scene::Projection m_projection;
    Vec3 m_position, m_forward, m_right, m_up;
    double m_tanHalfFov, m_orthoHeight;
    int m_width, m_height;
};

}  // namespace rayrad::raytrace
