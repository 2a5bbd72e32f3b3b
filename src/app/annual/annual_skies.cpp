#include <app/annual/annual_skies.h>

#include <scene/daylight/perez.h>
#include <scene/daylight/sun_position.h>

#include <tbb/parallel_for.h>

#include <cmath>

namespace rayrad::app {

namespace {

/// The hour's daylight as a scene's Daylight (the sky's distribution and scale), from the
/// weather file's irradiances.
scene::Daylight hourDaylight(const scene::WeatherHour& w, const scene::Daylight& axes, const scene::SunPosition& sun,
                             int dayOfYear) {
    scene::Daylight d = axes;
    d.channel.reset();
    d.kind = scene::SkyKind::Perez;
    d.sun = sun;
    const double zenith = std::min(sun.zenithDeg(), 90.0) * kPi / 180;  // twilight: the sky alone
    const double direct = sun.altitudeDeg > 0 ? w.directNormalIrradiance : 0.0;
    d.perez = scene::perezFromIrradiance(direct, w.diffuseHorizontalIrradiance, {zenith, dayOfYear, w.dewPointC});
    d.sunNormalIlluminance = d.perez->directNormalIlluminance;
    // As finishDaylight, but the zenith luminance left for skyHourOf to find with the
    // quadrature it makes anyway (one per hour of the year).
    const double altitude = sun.altitudeDeg * kPi / 180, azimuth = sun.azimuthDeg * kPi / 180;
    d.sunDirection = glm::normalize(d.toWorld(scene::skyDirection(altitude, azimuth)));
    d.distribution = scene::SkyDistribution::perez(d.perez->coefficients, kPi / 2 - altitude);
    d.skyHorizontalIlluminance = d.perez->diffuseHorizontalIlluminance;
    d.zenithLuminance = 0;
    return d;
}

}  // namespace

SkyHour skyHourOf(const scene::Daylight& d, const scene::SkyPatches& patches, const scene::SkyPatches& fine) {
    SkyHour h;
    h.lit = true;
    if (d.sun) h.sunAltitudeDeg = d.sun->altitudeDeg, h.sunAzimuthDeg = d.sun->azimuthDeg;
    h.diffuseHorizontal = d.skyHorizontalIlluminance;
    h.groundLuminance = d.groundReflectance * (d.skyHorizontalIlluminance + d.sunHorizontalIlluminance()) / kPi;
    if (d.hasDirectSun()) {
        h.sunNormal = d.sunNormalIlluminance;
        h.toSun = d.sunDirection;
        h.sunWeights = patches.weights(d.toLocal(d.sunDirection));
    }
    // L_j = ∫ tent_j L dω / Ω_j: the tents' sum keeps the sky's light (∫ Σ L_j tent_j dω =
    // ∫ L dω) and a narrow brightening (the sun's corona) is spread, not sampled.
    // One quadrature over the sky (about 2° fine for 145 patches): the tents' means and,
    // when the zenith luminance is still to be found, ∫ (L/L_z) cos Z dω.
    const Vec3 sunLocal = d.toLocal(d.sunDirection);
    std::vector<double> sum(static_cast<size_t>(patches.count()), 0.0);
    double horizontal = 0;  // sr
    patches.forEachDirection(48 * patches.multiplicationFactor(), [&](const Vec3& l, double dOmega) {
        const double relative = d.distribution.relative(l, sunLocal) * dOmega;
        horizontal += relative * l.z;
        const auto w = patches.weights(l);
        for (int k = 0; k < w.count; ++k) sum[static_cast<size_t>(w.patch[k])] += w.weight[k] * relative;
    });
    const double zenith =
        d.zenithLuminance > 0 ? d.zenithLuminance : horizontal > 0 ? d.skyHorizontalIlluminance / horizontal : 0.0;
    h.zenithLuminance = zenith;
    h.patchLuminance.resize(sum.size());
    for (int p = 0; p < patches.count(); ++p)
        h.patchLuminance[static_cast<size_t>(p)] =
            static_cast<float>(zenith * sum[static_cast<size_t>(p)] / patches.tentSolidAngle(p));
    h.fineLuminance.resize(static_cast<size_t>(fine.count()));
    for (int p = 0; p < fine.count(); ++p)
        h.fineLuminance[static_cast<size_t>(p)] =
            static_cast<float>(zenith * d.distribution.relative(fine.centre(p), sunLocal));
    return h;
}

namespace {

/// The sun at the middle of hour k of `weather`, at its place and time zone.
scene::SunPosition sunOfHour(const scene::WeatherFile& weather, size_t k) {
    scene::Site site;
    site.latitudeDeg = weather.latitudeDeg;
    site.longitudeDeg = weather.longitudeDeg;
    site.elevationM = weather.elevationM;
    const scene::WeatherHour& w = weather.hours[k];
    scene::LocalTime t;
    t.year = weather.hours.size() == 8784 ? 2020 : 2021;
    t.month = w.month, t.day = w.day, t.hour = w.hour - 1, t.minute = 30;
    t.utcOffsetHours = weather.timeZoneHours;
    return scene::sunPosition(t, site);
}

}  // namespace

std::vector<SkyHour> annualSkies(const scene::WeatherFile& weather, const scene::Daylight& axes,
                                 const scene::SkyPatches& patches, const scene::SkyPatches& fine) {
    std::vector<SkyHour> hours(weather.hours.size());
    tbb::parallel_for(size_t(0), hours.size(), [&](size_t k) {
        const scene::WeatherHour& w = weather.hours[k];
        const scene::SunPosition sun = sunOfHour(weather, k);
        SkyHour& h = hours[k];
        if (w.diffuseHorizontalIrradiance > 0 && sun.altitudeDeg > -6)  // civil twilight and day
            h = skyHourOf(hourDaylight(w, axes, sun, static_cast<int>(k / 24) + 1), patches, fine);
        h.month = w.month, h.day = w.day;
        h.clockHour = w.hour - 0.5;
        h.sunAltitudeDeg = sun.altitudeDeg, h.sunAzimuthDeg = sun.azimuthDeg;
    });
    return hours;
}

scene::Daylight yearHourDaylight(const scene::WeatherFile& weather, const scene::Daylight& axes, size_t k,
                                 const SkyHour& hour) {
    scene::Daylight d = hourDaylight(weather.hours[k], axes, sunOfHour(weather, k), static_cast<int>(k / 24) + 1);
    d.zenithLuminance = hour.zenithLuminance;
    return d;
}

std::vector<char> sunNodes(const std::vector<SkyHour>& hours, const scene::SkyPatches& patches) {
    std::vector<char> near(static_cast<size_t>(patches.count()), 0);
    for (const SkyHour& h : hours)
        if (h.sunNormal > 0)
            for (int k = 0; k < h.sunWeights.count; ++k)
                if (h.sunWeights.weight[k] > 0) near[static_cast<size_t>(h.sunWeights.patch[k])] = 1;
    return near;
}

}  // namespace rayrad::app
