// A year of skies from a weather file: each hour's sun and Perez sky, as the luminances of
// the sky patches and the ground that daylight coefficients are weighted with.
#pragma once

#include <scene/daylight/daylight.h>
#include <scene/daylight/sky_patches.h>
#include <scene/daylight/weather_file.h>

#include <vector>

namespace rayrad::app {

/// One hour's daylight, reduced to what the coefficients need.
struct SkyHour {
    int month = 1, day = 1;
    double clockHour = 0.5;      ///< local standard time of the hour's middle, h (EPW hour − ½)
    bool lit = false;            ///< some daylight: the sky's diffuse light or the sun
    std::vector<float> patchLuminance;  ///< cd/m², the sky's tent-weighted mean around each patch's centre (empty when not lit)
    std::vector<float> fineLuminance;   ///< cd/m², the sky's at each fine patch's centre (direct light)
    double groundLuminance = 0;  ///< cd/m²: ρ_g (E_dh + E_n sin α) / π
    double sunNormal = 0;        ///< E_n, lx (0: no direct sun)
    Vec3 toSun{0, 0, 1};         ///< world direction toward the sun
    scene::SkyPatches::Weights sunWeights;  ///< the patches around the sun and their weights
    double diffuseHorizontal = 0;  ///< E_dh, lx
    double sunAltitudeDeg = -90, sunAzimuthDeg = 0;
    double zenithLuminance = 0;    ///< L_z, cd/m² (from E_dh when the daylight did not give it)
};

/// One hour's daylight `d` (its sky's distribution and scale, sun, ground) as the
/// coefficients see it: each patch's luminance the sky's mean weighted by its tent,
/// ∫ tent_j L dω / Ω_j (a quadrature about 2° fine for 145 patches), each fine patch's the
/// sky's at its centre. With d.zenithLuminance 0 the zenith luminance is found from d's
/// E_dh by the same quadrature.
SkyHour skyHourOf(const scene::Daylight& d, const scene::SkyPatches& patches, const scene::SkyPatches& fine);

/// Every hour of `weather` at its own place and time zone (the sun at each hour's middle),
/// with the scene's axes and ground reflectance from `axes`: the Perez all-weather sky from
/// the hour's direct normal and diffuse horizontal irradiance and dew point (Perez 1990
/// efficacies), its zenith luminance from E_dh = L_z ∫ (L/L_z) cos Z dω (skyHourOf's
/// quadrature), the patches' luminance as skyHourOf.
std::vector<SkyHour> annualSkies(const scene::WeatherFile& weather, const scene::Daylight& axes,
                                 const scene::SkyPatches& patches, const scene::SkyPatches& fine);

/// Hour k of `weather` (0-based) as a scene's daylight with the axes and ground of `axes`:
/// the Perez sky and sun annualSkies weighs the coefficients with, scaled by `hour`'s
/// zenith luminance (for rendering that hour).
scene::Daylight yearHourDaylight(const scene::WeatherFile& weather, const scene::Daylight& axes, size_t k,
                                 const SkyHour& hour);

/// Per patch: whether the sun of some hour stands near its centre (a weight of its
/// interpolation), so that a sun there is worth solving.
std::vector<char> sunNodes(const std::vector<SkyHour>& hours, const scene::SkyPatches& patches);

}  // namespace rayrad::app
