// The sun in an hour of the year: its direct light at a sensor, exactly, and the factor its
// interreflected light from the suns solved around it takes.
#pragma once

#include <app/annual/opening_samples.h>
#include <app/pipeline.h>
#include <scene/daylight/sky_patches.h>

#include <memory>
#include <vector>

namespace rayrad::app {

/// The sun's light in an hour of the year: its direct light at a sensor, exactly, and the
/// factor its interreflected light from the suns around it takes.
class SunLight {
  public:
    SunLight(const PipelineRun& run, const scene::SkyPatches& patches);
    ~SunLight();
    /// Direct light at the unit normal n of point x per lx of direct normal illuminance,
    /// toward the unit world direction `toSun`: cosθ · τ of the glazings on the way ·
    /// whether the way out is clear (one ray; the sun as a point).
    double directAt(const Vec3& x, const Vec3& n, const Vec3& toSun) const;
    /// The sun's interreflected light is interpolated between the suns at the centres of
    /// the patches around it (weights w_j); k = Φ(s) / Σ_j w_j Φ(s_j) makes it bring in what
    /// the sun itself lets in through the openings: Φ(s) = Σ_o A_o τ(θ) cosθ V_o(s), V_o the
    /// share of 8 × 8 points on opening o whose way toward s is clear.
    double sunScale(const Vec3& toSun, const scene::SkyPatches::Weights& w) const;
    /// Φ(s), lm per lx of direct normal illuminance toward the unit world direction s.
    double entering(const Vec3& toSky) const;

  private:
    const PipelineRun& m_run;
    std::unique_ptr<radiosity::DirectLight> m_openingLights;  ///< every opening (under a uniform sky)
    std::vector<OpeningSamples> m_openings;                   ///< 8 × 8 points a triangle
    std::vector<double> m_nodeEntering;  ///< Φ at each patch's centre
    double m_far = 0;                    ///< m: beyond the scene from anywhere in it
};

}  // namespace rayrad::app
