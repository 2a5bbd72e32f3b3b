#include <scene/daylight/daylight.h>

#include <algorithm>
#include <cmath>

namespace rayrad::scene {

double Daylight::sunHorizontalIlluminance() const {
    return hasDirectSun() ? sunNormalIlluminance * std::sin(sun->altitudeDeg * kPi / 180) : 0.0;
}

double Daylight::luminance(const Vec3& w) const {
    const Vec3 local = toLocal(w);
    if (channel) {
        if (local.z < 0) return channel->patch == SkyChannel::kGround ? 1.0 : 0.0;
        return channel->patch >= 0 ? channel->patches->weight(channel->patch, local) : 0.0;
    }
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

Daylight channelDaylight(const Daylight& d, const SkyChannel& channel) {
    Daylight c = d;
    c.channel = channel;
    c.sun.reset();
    c.sunNormalIlluminance = 0;
    c.perez.reset();
    c.zenithLuminance = 0;
    c.skyHorizontalIlluminance = 0;
    c.medianExternalIlluminance.reset();
    return c;
}

Daylight sunChannelDaylight(const Daylight& d, const Vec3& local) {
    Daylight c = channelDaylight(d, {nullptr, SkyChannel::kDark});
    const double altitude = std::asin(std::clamp(local.z, -1.0, 1.0)) * 180 / kPi;
    const double azimuth = std::atan2(local.x, local.y) * 180 / kPi;
    c.sun = SunPosition{altitude, azimuth < 0 ? azimuth + 360 : azimuth};
    c.sunDirection = glm::normalize(c.toWorld(local));
    c.sunNormalIlluminance = 1;
    return c;
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
    const Vec3 local = skyDirection(altitude, azimuth);
    d.sunDirection = glm::normalize(d.toWorld(local));
    d.distribution = d.perez ? SkyDistribution::perez(d.perez->coefficients, kPi / 2 - altitude)
                             : SkyDistribution(d.kind, d.cieType, kPi / 2 - altitude);
    const double factor = d.distribution.horizontalFactor(local);  // sr
    d.zenithLuminance = zenithLuminance > 0 ? zenithLuminance : horizontal / factor;
    d.skyHorizontalIlluminance = d.zenithLuminance * factor;
}

}  // namespace rayrad::scene
