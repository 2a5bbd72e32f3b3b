#include <scene/daylight/daylight_parser.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace rayrad::scene {

namespace {

/// "sun": where it is, from a place and a local time or as altitude and azimuth, and its
/// direct normal illuminance (lx; absent or 0: the sun only places the sky's brightening).
void parseSun(JsonObject s, Daylight& d) {
    const bool byPlace = s.has("latitude") || s.has("longitude") || s.has("date") || s.has("time");
    const bool byAngles = s.has("altitude") || s.has("azimuth");
    if (byPlace && byAngles) {
        s.error("altitude", "give the sun either by place and time (latitude, longitude, utc_offset, date, time) "
                            "or by altitude and azimuth, not both");
        return;
    }
    if (s.has("direct_normal_illuminance")) d.sunNormalIlluminance = s.nonNegative("direct_normal_illuminance", 0.0);
    if (d.sunNormalIlluminance > 2e5)
        s.error("direct_normal_illuminance",
                fmt::format("{} lx is more than the sun gives above the atmosphere (about 128 000 lx)",
                            d.sunNormalIlluminance));
    if (byAngles) {
        for (const char* key : {"altitude", "azimuth"}) s.required(key);
        const double altitude = s.number("altitude", 45), azimuth = s.number("azimuth", 180);
        if (!(altitude >= -90 && altitude <= 90))
            s.error("altitude", fmt::format("the sun's altitude must be within [−90°, 90°], got {}", altitude));
        d.sun = SunPosition{altitude, azimuth};
        s.finish();
        return;
    }
    for (const char* key : {"latitude", "longitude", "utc_offset", "date", "time"}) s.required(key);
    Site site;
    site.latitudeDeg = s.number("latitude", 0);
    site.longitudeDeg = s.number("longitude", 0);
    site.elevationM = s.number("elevation", 0);
    site.deltaTSeconds = s.number("delta_t", site.deltaTSeconds);
    if (!(site.latitudeDeg >= -90 && site.latitudeDeg <= 90))
        s.error("latitude", fmt::format("a latitude lies within [−90°, 90°], got {}", site.latitudeDeg));
    if (!(site.longitudeDeg >= -180 && site.longitudeDeg <= 180))
        s.error("longitude", fmt::format("a longitude lies within [−180°, 180°] (east positive), got {}",
                                         site.longitudeDeg));
    if (!(site.elevationM >= -500 && site.elevationM <= 9000))
        s.error("elevation", fmt::format("expected a height above sea level in [−500, 9000] m, got {}", site.elevationM));
    LocalTime time;
    time.utcOffsetHours = s.number("utc_offset", 0);
    if (!(std::abs(time.utcOffsetHours) <= 14))
        s.error("utc_offset", fmt::format("a time zone's offset from UTC lies within ±14 h, got {}",
                                          time.utcOffsetHours));
    const std::string date = s.string("date").value_or("2000-01-01"), clock = s.string("time").value_or("12:00");
    if (auto problem = parseDateTime(date, clock, time)) s.error(s.has("date") ? "date" : "time", *problem);
    s.finish();
    if (s.context().errors == 0) d.sun = sunPosition(time, site);
}

/// "sky": its type and one scale.
void parseSky(JsonObject s, Daylight& d, double& zenith, double& horizontal) {
    s.required("type");
    const std::string type = s.string("type").value_or("cie_overcast");
    static const std::vector<std::string> kTypes = {"uniform", "cie_overcast", "cie_standard", "cie_clear"};
    if (type == "uniform") {
        d.kind = SkyKind::Uniform;
    } else if (type == "cie_overcast") {
        d.kind = SkyKind::CieOvercast;
    } else if (type == "cie_standard" || type == "cie_clear") {
        d.kind = SkyKind::CieStandard;
        if (type == "cie_standard") s.required("cie_type");
        d.cieType = s.integer("cie_type", type == "cie_clear" ? 12 : 1, 1, 15);
    } else {
        const std::string hint = closestMatch(type, kTypes);
        s.error("type", fmt::format("unknown sky \"{}\" ({})", type,
                                    hint.empty() ? "expected uniform, cie_overcast, cie_standard or cie_clear"
                                                 : fmt::format("did you mean \"{}\"?", hint)));
    }
    const bool hasZenith = s.has("zenith_luminance"), hasHorizontal = s.has("diffuse_horizontal_illuminance");
    if (hasZenith == hasHorizontal)
        s.error("zenith_luminance", "a sky needs exactly one scale: \"zenith_luminance\" (cd/m²) or "
                                    "\"diffuse_horizontal_illuminance\" (lx, the unobstructed sky on a horizontal plane)");
    if (hasZenith) zenith = s.positive("zenith_luminance", 1.0);
    if (hasHorizontal) horizontal = s.positive("diffuse_horizontal_illuminance", 1.0);
    s.finish();
}

}  // namespace

Daylight parseDaylight(JsonObject o) {
    Daylight d;
    d.where = o.path();
    const Vec3 up = o.vec3("up").value_or(Vec3(0, 1, 0)), north = o.vec3("north").value_or(Vec3(0, 0, -1));
    if (!setSkyAxes(d, up, north)) o.error("north", "\"up\" and \"north\" must be non-zero and not parallel");
    double zenith = 0, horizontal = 0;
    o.required("sky");
    if (auto s = o.object("sky")) parseSky(*s, d, zenith, horizontal);
    if (auto s = o.object("sun")) parseSun(*s, d);
    if (o.has("ground_reflectance")) {
        d.groundReflectance = o.nonNegative("ground_reflectance", 0.2);
        if (d.groundReflectance >= 1)
            o.error("ground_reflectance", fmt::format("expected a reflectance in [0, 1), got {}", d.groundReflectance));
    }
    if (o.has("median_external_illuminance"))
        d.medianExternalIlluminance = o.positive("median_external_illuminance", 10000);
    o.finish();
    if (o.context().errors > 0) return d;
    SkyDistribution probe(d.kind, d.cieType, 0.0);
    if (probe.needsSun() && !d.sun)
        o.error("sun", fmt::format("CIE sky type {} is brighter toward the sun: give the sun's place and time or its "
                                   "altitude and azimuth",
                                   d.cieType));
    if (d.sunNormalIlluminance > 0 && !d.sun)
        o.error("sun", "a direct normal illuminance needs the sun's position");
    if (o.context().errors == 0) finishDaylight(d, zenith, horizontal);
    return d;
}

}  // namespace rayrad::scene
