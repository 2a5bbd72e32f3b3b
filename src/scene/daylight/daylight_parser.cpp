#include <scene/daylight/daylight_parser.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace rayrad::scene {

namespace {

/// "sun": where it is, from a place and a local time or as altitude and azimuth, and its
/// direct normal illuminance (lx; absent or 0: the sun only places the sky's brightening).
void parseSun(JsonObject s, Daylight& d, int& dayOfYear) {
    const bool byPlace = s.has("latitude") || s.has("longitude") || s.has("date") || s.has("time");
    const bool byAngles = s.has("altitude") || s.has("azimuth");
    if (byPlace && byAngles) {
        s.error("altitude",
                "give the sun either by place and time (latitude, longitude, utc_offset, date, time) "
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
        s.error("longitude",
                fmt::format("a longitude lies within [−180°, 180°] (east positive), got {}", site.longitudeDeg));
    if (!(site.elevationM >= -500 && site.elevationM <= 9000))
        s.error("elevation",
                fmt::format("expected a height above sea level in [−500, 9000] m, got {}", site.elevationM));
    LocalTime time;
    time.utcOffsetHours = s.number("utc_offset", 0);
    if (!(std::abs(time.utcOffsetHours) <= 14))
        s.error("utc_offset",
                fmt::format("a time zone's offset from UTC lies within ±14 h, got {}", time.utcOffsetHours));
    const std::string date = s.string("date").value_or("2000-01-01"), clock = s.string("time").value_or("12:00");
    if (auto problem = parseDate(date, time)) s.error("date", *problem);
    if (auto problem = parseTime(clock, time)) s.error("time", *problem);
    s.finish();
    if (s.context().errors == 0) {
        d.sun = sunPosition(time, site);
        d.site = site;
        dayOfYear =
            static_cast<int>(julianDay(time.year, time.month, time.day, 12) - julianDay(time.year, 1, 1, 12)) + 1;
    }
}

/// A Perez sky's inputs: one hour's direct normal and diffuse horizontal light, as
/// irradiance (W/m²) or illuminance (lx), and the dew point (°C).
struct PerezInput {
    bool irradiance = true;
    double direct = 0, diffuse = 0, dewPoint = 11;
};

void parsePerez(JsonObject& s, PerezInput& in) {
    const bool byIrradiance = s.has("direct_normal_irradiance") || s.has("diffuse_horizontal_irradiance");
    const bool byIlluminance = s.has("direct_normal_illuminance") || s.has("diffuse_horizontal_illuminance");
    if (byIrradiance == byIlluminance) {
        s.error("diffuse_horizontal_irradiance",
                "a Perez sky needs one hour's light, either \"direct_normal_irradiance\" and "
                "\"diffuse_horizontal_irradiance\" (W/m²) or \"direct_normal_illuminance\" and "
                "\"diffuse_horizontal_illuminance\" (lx)");
        return;
    }
    in.irradiance = byIrradiance;
    const char* direct = byIrradiance ? "direct_normal_irradiance" : "direct_normal_illuminance";
    const char* diffuse = byIrradiance ? "diffuse_horizontal_irradiance" : "diffuse_horizontal_illuminance";
    s.required(direct);
    s.required(diffuse);
    in.direct = s.nonNegative(direct, 0.0);
    in.diffuse = s.positive(diffuse, 1.0);
    const double ceiling = byIrradiance ? 1500 : 2e5;  // about what reaches the ground at most
    for (const char* key : {direct, diffuse})
        if (s.has(key) && s.number(key, 0) > ceiling)
            s.error(key, fmt::format("{} {} is more than the sun and sky give on the ground", s.number(key, 0),
                                     byIrradiance ? "W/m²" : "lx"));
    in.dewPoint = s.number("dew_point", in.dewPoint);
    if (!(in.dewPoint >= -60 && in.dewPoint <= 40))
        s.error("dew_point", fmt::format("expected a dew point in [−60, 40] °C, got {}", in.dewPoint));
    if (s.has("zenith_luminance"))
        s.error("zenith_luminance", "a Perez sky takes its scale from its diffuse light, not a zenith luminance");
}

/// "sky": its type and one scale (a Perez sky: its hour's light, `perez`).
void parseSky(JsonObject s, Daylight& d, double& zenith, double& horizontal, std::optional<PerezInput>& perez) {
    s.required("type");
    const std::string type = s.string("type").value_or("cie_overcast");
    static const std::vector<std::string> kTypes = {"uniform", "cie_overcast", "cie_standard", "cie_clear", "perez"};
    if (type == "perez") {
        d.kind = SkyKind::Perez;
        perez.emplace();
        parsePerez(s, *perez);
        s.finish();
        return;
    }
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
                                    hint.empty() ? "expected uniform, cie_overcast, cie_standard, cie_clear or perez"
                                                 : fmt::format("did you mean \"{}\"?", hint)));
    }
    const bool hasZenith = s.has("zenith_luminance"), hasHorizontal = s.has("diffuse_horizontal_illuminance");
    if (hasZenith == hasHorizontal)
        s.error("zenith_luminance",
                "a sky needs exactly one scale: \"zenith_luminance\" (cd/m²) or "
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
    int dayOfYear = 0;  // 0: unknown (the sun given by its angles)
    std::optional<PerezInput> perez;
    o.required("sky");
    if (auto s = o.object("sky")) parseSky(*s, d, zenith, horizontal, perez);
    if (auto s = o.object("sun")) parseSun(*s, d, dayOfYear);
    if (o.has("ground_reflectance")) {
        d.groundReflectance = o.nonNegative("ground_reflectance", 0.2);
        if (d.groundReflectance >= 1)
            o.error("ground_reflectance", fmt::format("expected a reflectance in [0, 1), got {}", d.groundReflectance));
    }
    if (o.has("median_external_illuminance"))
        d.medianExternalIlluminance = o.positive("median_external_illuminance", 10000);
    o.finish();
    if (o.context().errors > 0) return d;
    if (perez) {
        if (!d.sun) {
            o.error("sun",
                    "a Perez sky is brighter toward the sun: give the sun's place and time or its altitude "
                    "and azimuth");
            return d;
        }
        if (d.sunNormalIlluminance > 0) {
            o.error("sun",
                    "a Perez sky gives the sun's direct light itself: leave out the sun's "
                    "\"direct_normal_illuminance\"");
            return d;
        }
        // The model's sun is no lower than the horizon (twilight: the sky's diffuse light only).
        const PerezConditions conditions{std::min(d.sun->zenithDeg(), 90.0) * kPi / 180, dayOfYear, perez->dewPoint};
        const double direct = d.sun->altitudeDeg > 0 ? perez->direct : 0.0;
        d.perez = perez->irradiance ? perezFromIrradiance(direct, perez->diffuse, conditions)
                                    : perezFromIlluminance(direct, perez->diffuse, conditions);
        d.sunNormalIlluminance = d.perez->directNormalIlluminance;
        horizontal = d.perez->diffuseHorizontalIlluminance;
    }
    SkyDistribution probe(d.kind, d.cieType, 0.0);
    if (probe.needsSun() && !d.sun && !perez)
        o.error("sun", fmt::format("CIE sky type {} is brighter toward the sun: give the sun's place and time or its "
                                   "altitude and azimuth",
                                   d.cieType));
    if (d.sunNormalIlluminance > 0 && !d.sun) o.error("sun", "a direct normal illuminance needs the sun's position");
    if (o.context().errors == 0) finishDaylight(d, zenith, horizontal);
    return d;
}

}  // namespace rayrad::scene
