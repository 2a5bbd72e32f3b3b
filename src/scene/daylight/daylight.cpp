#include <scene/daylight/daylight.h>

#include <cmath>

namespace rayrad::scene {

double Daylight::sunHorizontalIlluminance() const {
    return hasDirectSun() ? sunNormalIlluminance * std::sin(sun->altitudeDeg * kPi / 180) : 0.0;
}

double Daylight::luminance(const Vec3& w) const {
    const Vec3 local = toLocal(w);
    if (local.z < 0) return groundReflectance * (skyHorizontalIlluminance + sunHorizontalIlluminance()) / kPi;
    return zenithLuminance * distribution.relative(local, toLocal(sunDirection));
}

double Daylight::sunDiskLuminance() const {
    if (!hasDirectSun()) return 0.0;
    return sunNormalIlluminance / (2 * kPi * (1 - std::cos(kSunAngularRadius)));
}

bool Daylight::inSunDisk(const Vec3& w) const {
    return hasDirectSun() && glm::dot(w, sunDirection) >= std::cos(kSunAngularRadius);
}

bool setSkyAxes(Daylight& d, const Vec3& up, const Vec3& north) {
    const auto u = unitDirection(up);
    if (!u) return false;
    const auto n = unitDirection(north - glm::dot(north, *u) * *u);
    if (!n || glm::length(glm::cross(*u, *n)) < 0.5) return false;
    d.up = *u;
    d.north = *n;
    d.east = glm::cross(d.north, d.up);  // x east, y north, z up: a right-handed frame
    return true;
}

void finishDaylight(Daylight& d, double zenithLuminance, double horizontal) {
    const double altitude = d.sun ? d.sun->altitudeDeg * kPi / 180 : kPi / 2;
    const double azimuth = d.sun ? d.sun->azimuthDeg * kPi / 180 : 0;
    // Azimuth from north toward east: the local direction (sin az cos alt, cos az cos alt, sin alt).
    const Vec3 local(std::sin(azimuth) * std::cos(altitude), std::cos(azimuth) * std::cos(altitude), std::sin(altitude));
    d.sunDirection = glm::normalize(local.x * d.east + local.y * d.north + local.z * d.up);
    d.distribution = d.perez ? SkyDistribution::perez(d.perez->coefficients, kPi / 2 - altitude)
                             : SkyDistribution(d.kind, d.cieType, kPi / 2 - altitude);
    const double factor = d.distribution.horizontalFactor(local);  // sr
    d.zenithLuminance = zenithLuminance > 0 ? zenithLuminance : horizontal / factor;
    d.skyHorizontalIlluminance = d.zenithLuminance * factor;
}

}  // namespace rayrad::scene
