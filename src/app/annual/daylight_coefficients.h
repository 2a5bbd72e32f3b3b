// Daylight coefficients: what each sky patch (and the ground) of 1 cd/m² does at every
// sensor, direct and interreflected, and what a sun of 1 lx at each patch's centre adds by
// interreflection, from one radiosity solve per channel; and the sun's direct light at a
// sensor from any direction, exactly.
#pragma once

#include <app/pipeline.h>
#include <scene/daylight/sky_patches.h>

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

/// The sky's direct light at each sensor by direction, finer than the solves' channels:
/// what each tent of a fine sky subdivision (and the ground) of 1 cd/m² gives the point
/// straight through the openings, E = Σ_y τ cosθ_x cosθ_y / r² ΔA V over points y on the
/// openings (32 × 32 a triangle), each direction shared among the tents around it.
struct DirectSkyCoefficients {
    std::shared_ptr<const scene::SkyPatches> patches;
    /// Per point: (tent, lx per cd/m²), the ground as tent patches->count().
    std::vector<std::vector<std::pair<uint32_t, float>>> terms;
    double cpuSeconds = 0;
};
DirectSkyCoefficients directSkyCoefficients(const PipelineRun& run, std::shared_ptr<const scene::SkyPatches> fine);

struct DaylightCoefficients {
    std::shared_ptr<const scene::SkyPatches> patches;
    size_t points = 0;  ///< the scene's sensors (grid points included), in their order
    /// Interreflected light, lx at point i per cd/m² of channel c: [c · points + i].
    /// Channels: the sky patches' tents 0 … P−1 (SkyPatches::weight), then the ground.
    std::vector<double> indirect;
    /// The direct light of the sky and the ground, on a finer subdivision.
    DirectSkyCoefficients skyDirect;
    /// lx of interreflected light at point i per lx of direct normal illuminance from a sun
    /// at the centre of patch j: [sunSlot[j] · points + i]; sunSlot[j] −1 where no sun was
    /// solved (the year's sun does not come near, or no opening lets it in: zero).
    std::vector<double> sunIndirect;
    std::vector<int> sunSlot;
    int solvedChannels = 0, solvedSuns = 0;  ///< solves run (channels no opening lets in are zero, not solved)
    double solveCpuSeconds = 0, solveWallSeconds = 0;

    int channels() const { return patches->count() + 1; }
    int groundChannel() const { return patches->count(); }
    double indirectAt(int c, size_t i) const { return indirect[static_cast<size_t>(c) * points + i]; }
    double sunIndirectAt(int patch, size_t i) const {
        const int slot = sunSlot[static_cast<size_t>(patch)];
        return slot < 0 ? 0.0 : sunIndirect[static_cast<size_t>(slot) * points + i];
    }
};

/// Solves `run`'s scene (prepared: preparePipeline; its daylight is replaced, its electric
/// light removed) once per channel, sharing the mesh, the visibility and the clusters:
/// each sky patch's tent, the ground, and a sun at the centre of each patch `sunNear`
/// marks. Each solve's direct light and interreflection are those of an ordinary daylight
/// solve under that sky; the sensors keep its interreflected light, their direct light
/// comes from directSkyCoefficients on the `fine` patches. A progress line unless `quiet`.
DaylightCoefficients solveDaylightCoefficients(PipelineRun& run, std::shared_ptr<const scene::SkyPatches> patches,
                                               std::shared_ptr<const scene::SkyPatches> fine,
                                               const std::vector<char>& sunNear, bool quiet);

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
