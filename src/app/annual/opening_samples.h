// The openings of a scene as the annual study samples them: points evenly over each, and
// the glazings every ray from inside crosses.
#pragma once

#include <radiosity/radiosity.h>
#include <scene/scene.h>

#include <memory>
#include <vector>

namespace rayrad::app {

/// An opening of the scene, with points evenly over it (a barycentric grid on each of
/// its triangles, `perSide` across for a triangle of average size).
struct OpeningSamples {
    Vec3 out{0.0};                 ///< unit, toward the sky
    double transmittance = 1;      ///< normal τ
    double area = 0;               ///< m²
    std::vector<Vec3> points;
    std::vector<double> pointArea;  ///< m² each stands for
};
std::vector<OpeningSamples> openingSamples(const scene::Scene& scene, int perSide);

/// Every opening of the scene as a light under a uniform sky: what a ray crosses on its way
/// out (DirectLight::openingTransmittance), whatever the scene's own sky.
std::unique_ptr<radiosity::DirectLight> openingGlazings(const scene::Scene& scene);

}  // namespace rayrad::app
