// The daylight of a scene: the sky, the sun and the ground, in the scene's own axes.
#pragma once

#include <core/math.h>
#include <scene/daylight/perez.h>
#include <scene/daylight/sky.h>
#include <scene/daylight/sky_patches.h>
#include <scene/daylight/sun_position.h>

#include <cmath>
#include <memory>
#include <optional>
#include <string>

namespace rayrad::scene {

/// The sun's angular radius seen from the Earth, rad (its disk is 0.533° across).
constexpr double kSunAngularRadius = 0.2665 * kPi / 180;

/// One channel of daylight coefficients: the sky's luminance the tent of one sky patch
/// (1 cd/m² at its centre, falling linearly to 0 at its neighbours' centres:
/// SkyPatches::weight) with the ground dark, or (patch −1) the ground of 1 cd/m² below the
/// horizon and the sky dark; no sun.
struct SkyChannel {
    static constexpr int kGround = -1, kDark = -2;
    std::shared_ptr<const SkyPatches> patches;
    int patch = kGround;  ///< the lit patch; kGround: the ground; kDark: neither (a sun alone)
};

/// The sky over the scene, the sun and the ground below the horizon. Directions are world
/// space, unit; the sky frame is x east, y north, z up (`up`, `north` given in the scene).
struct Daylight {
    std::string where;  ///< JSON pointer, for messages
    Vec3 up{0, 1, 0}, north{0, 0, -1}, east{1, 0, 0};
    SkyKind kind = SkyKind::CieOvercast;
    int cieType = 0;  ///< 1 … 15 for SkyKind::CieStandard
    std::optional<PerezSky> perez;  ///< for SkyKind::Perez: ε, Δ and a … e of the hour
    SkyDistribution distribution;
    double zenithLuminance = 0;            ///< L_z, cd/m²
    double skyHorizontalIlluminance = 0;   ///< E_dh: the unobstructed sky on a horizontal plane, lx
    std::optional<SunPosition> sun;        ///< where the sun is (given, or from a place and time)
    std::optional<Site> site;              ///< the place, when the sun is placed by place and time
    Vec3 sunDirection{0, 0, 1};            ///< toward the sun, world space
    double sunNormalIlluminance = 0;       ///< E_n, lx on a plane facing the sun (0: no direct sun)
    double groundReflectance = 0.2;        ///< of the ground below the horizon
    /// EN 17037 method 1: the site's median external diffuse illuminance E_v,d,med, lx
    /// (given: grids report the shares of points above D_T = 300 / E and D_TM = 100 / E).
    std::optional<double> medianExternalIlluminance;
    /// When set, the sky and ground are this channel's instead (the other fields are then
    /// not looked at by luminance(); there is no sun).
    std::optional<SkyChannel> channel;

    /// A world direction in the sky frame (x east, y north, z up).
    Vec3 toLocal(const Vec3& w) const { return {glm::dot(w, east), glm::dot(w, north), glm::dot(w, up)}; }
    /// A direction of the sky frame in world space.
    Vec3 toWorld(const Vec3& l) const { return l.x * east + l.y * north + l.z * up; }
    /// Whether the sun shines on the scene: a direct illuminance and the sun above the horizon.
    bool hasDirectSun() const { return sunNormalIlluminance > 0 && sun && sun->altitudeDeg > 0; }
    /// The direct sun on a horizontal plane, E_n sin(altitude), lx (0 without direct sun).
    double sunHorizontalIlluminance() const;
    /// Luminance (cd/m²) seen along the unit world direction w from outdoors, without the
    /// sun's disk: the sky above the horizon, L_z · L/L_z; below it the ground, a diffuse
    /// plane lit by the whole sky and the sun, ρ_g (E_dh + E_n sin α_s) / π.
    double luminance(const Vec3& w) const;
    /// The luminance of the sun's disk, E_n / Ω_sun, cd/m² (Ω_sun = 2π (1 − cos 0.2665°)).
    double sunDiskLuminance() const;
    /// Whether the unit direction w points into the sun's disk.
    bool inSunDisk(const Vec3& w) const;
};

/// The unit direction (x east, y north, z up) of altitude and azimuth (from north toward
/// east), rad: (sin az cos alt, cos az cos alt, sin alt).
inline Vec3 skyDirection(double altitude, double azimuth) {
    return {std::sin(azimuth) * std::cos(altitude), std::cos(azimuth) * std::cos(altitude), std::sin(altitude)};
}

/// The sky frame's axes from `up` and `north` (north made perpendicular to up), nothing
/// when they are parallel or zero.
bool setSkyAxes(Daylight& d, const Vec3& up, const Vec3& north);

/// `d` turned into one channel of daylight coefficients (its axes kept).
Daylight channelDaylight(const Daylight& d, const SkyChannel& channel);

/// `d` turned into a sun of 1 lx direct normal illuminance toward the sky frame's unit
/// direction `local`, with the sky and the ground dark (its axes kept).
Daylight sunChannelDaylight(const Daylight& d, const Vec3& local);

/// Puts the sun at `position` and fills the zenith luminance from one scale: the given
/// zenith luminance, or (when `zenithLuminance` ≤ 0) the sky's horizontal illuminance
/// `horizontal`, L_z = E_dh / ∫ (L/L_z) cos Z dω.
void finishDaylight(Daylight& d, double zenithLuminance, double horizontal);

}  // namespace rayrad::scene
