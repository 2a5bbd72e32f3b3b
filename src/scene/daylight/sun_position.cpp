#include <scene/daylight/sun_position.h>

#include <core/math.h>

#include <fmt/format.h>

#include <cmath>
#include <cstdio>

namespace rayrad::scene {

namespace {
constexpr double kDeg = kPi / 180;

/// An angle reduced to [0, 360) degrees.
double wrapDegrees(double a) {
    a = std::fmod(a, 360.0);
    return a < 0 ? a + 360 : a;
}
}  // namespace

bool isValidDate(int year, int month, int day) {
    if (month < 1 || month > 12 || day < 1) return false;
    static const int kDays[12] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
    const bool leap = (year % 4 == 0 && year % 100 != 0) || year % 400 == 0;
    return day <= kDays[month - 1] + (month == 2 && leap ? 1 : 0);
}

double julianDay(int year, int month, int day, double hourUtc) {
    // Meeus (7.1): January and February count as months 13 and 14 of the year before.
    int y = year, m = month;
    if (m <= 2) y -= 1, m += 12;
    const int a = y / 100;
    const int b = 2 - a + a / 4;  // the Gregorian correction
    return std::floor(365.25 * (y + 4716)) + std::floor(30.6001 * (m + 1)) + day + b - 1524.5 + hourUtc / 24;
}

SunPosition sunPosition(const LocalTime& time, const Site& site) {
    const double hourUtc = time.hour + time.minute / 60.0 + time.second / 3600.0 - time.utcOffsetHours;
    const double jd = julianDay(time.year, time.month, time.day, hourUtc);  // UT
    const double jde = jd + site.deltaTSeconds / 86400;                     // TT
    const double T = (jde - 2451545.0) / 36525;                             // Julian centuries of TT from J2000

    // The sun's geometric mean longitude and mean anomaly (25.2, 25.3), the Earth's
    // orbital eccentricity (25.4) and the equation of the centre, degrees.
    const double L0 = wrapDegrees(280.46646 + T * (36000.76983 + T * 0.0003032));
    const double M = wrapDegrees(357.52911 + T * (35999.05029 - T * 0.0001537));
    const double C = (1.914602 - T * (0.004817 + T * 0.000014)) * std::sin(M * kDeg) +
                     (0.019993 - T * 0.000101) * std::sin(2 * M * kDeg) + 0.000289 * std::sin(3 * M * kDeg);
    const double trueLongitude = L0 + C;
    const double e = 0.016708634 - T * (0.000042037 + T * 0.0000001267);
    const double v = M + C;                                                     // true anomaly
    const double R = 1.000001018 * (1 - e * e) / (1 + e * std::cos(v * kDeg));  // distance, AU (25.5)

    // Nutation in longitude and obliquity (ch. 22, the terms above 0.1″), degrees.
    const double omega = 125.04452 - T * 1934.136261;                              // the Moon's ascending node
    const double Ls = 280.4665 + 36000.7698 * T, Lm = 218.3165 + 481267.8813 * T;  // mean longitudes of sun and moon
    const double dPsi = (-17.20 * std::sin(omega * kDeg) - 1.32 * std::sin(2 * Ls * kDeg) -
                         0.23 * std::sin(2 * Lm * kDeg) + 0.21 * std::sin(2 * omega * kDeg)) /
                        3600;
    const double dEps = (9.20 * std::cos(omega * kDeg) + 0.57 * std::cos(2 * Ls * kDeg) +
                         0.10 * std::cos(2 * Lm * kDeg) - 0.09 * std::cos(2 * omega * kDeg)) /
                        3600;
    // Mean obliquity of the ecliptic (22.2), and the true one.
    const double eps0 = 23.0 + 26.0 / 60 + (21.448 - T * (46.8150 + T * (0.00059 - T * 0.001813))) / 3600;
    const double eps = eps0 + dEps;
    // Apparent longitude: nutation, and the aberration −20.4898″ / R.
    const double lambda = trueLongitude + dPsi - 20.4898 / 3600 / R;

    // Right ascension and declination (13.3, 13.4; the sun's latitude < 1.2″ is left out).
    const double alpha = std::atan2(std::cos(eps * kDeg) * std::sin(lambda * kDeg), std::cos(lambda * kDeg)) / kDeg;
    const double delta = std::asin(std::sin(eps * kDeg) * std::sin(lambda * kDeg)) / kDeg;

    // Apparent sidereal time at Greenwich (12.4, in UT, plus the equation of the equinoxes).
    const double Tu = (jd - 2451545.0) / 36525;
    const double theta0 = wrapDegrees(280.46061837 + 360.98564736629 * (jd - 2451545.0) + Tu * Tu * 0.000387933 -
                                      Tu * Tu * Tu / 38710000 + dPsi * std::cos(eps * kDeg));
    const double H = wrapDegrees(theta0 + site.longitudeDeg - alpha);  // local hour angle

    // Topocentric: the parallax of the sun's 8.794″ / R horizontal parallax (Meeus ch. 40,
    // to first order in it), for an observer at the site's height above the ellipsoid.
    const double phi = site.latitudeDeg * kDeg;
    const double u = std::atan(0.99664719 * std::tan(phi));
    const double rhoSin = 0.99664719 * std::sin(u) + site.elevationM / 6378140 * std::sin(phi);
    const double rhoCos = std::cos(u) + site.elevationM / 6378140 * std::cos(phi);
    const double xi = 8.794 / 3600 / R * kDeg;  // rad
    const double dAlpha = std::atan2(-rhoCos * std::sin(xi) * std::sin(H * kDeg),
                                     std::cos(delta * kDeg) - rhoCos * std::sin(xi) * std::cos(H * kDeg));
    const double deltaTopo = std::atan2((std::sin(delta * kDeg) - rhoSin * std::sin(xi)) * std::cos(dAlpha),
                                        std::cos(delta * kDeg) - rhoCos * std::sin(xi) * std::cos(H * kDeg));
    const double Htopo = H * kDeg - dAlpha;

    // Altitude and azimuth (13.5, 13.6; azimuth turned to count from north).
    const double sinAlt = std::sin(phi) * std::sin(deltaTopo) + std::cos(phi) * std::cos(deltaTopo) * std::cos(Htopo);
    const double altitude = std::asin(std::clamp(sinAlt, -1.0, 1.0)) / kDeg;
    const double azimuthSouth =
        std::atan2(std::sin(Htopo), std::cos(Htopo) * std::sin(phi) - std::tan(deltaTopo) * std::cos(phi)) / kDeg;

    // Atmospheric refraction (Bennett, as in NREL's SPA, eq. 42), while the sun is up.
    double refraction = 0;
    constexpr double kSunRadius = 0.26667;  // degrees
    if (altitude >= -(kSunRadius + 0.5667))
        refraction = site.pressureMbar / 1010 * 283 / (273 + site.temperatureC) * 1.02 /
                     (60 * std::tan((altitude + 10.3 / (altitude + 5.11)) * kDeg));
    return {altitude + refraction, wrapDegrees(azimuthSouth + 180)};
}

std::optional<std::string> parseDate(const std::string& date, LocalTime& t) {
    char tail = 0;
    if (std::sscanf(date.c_str(), "%d-%d-%d%c", &t.year, &t.month, &t.day, &tail) != 3)
        return fmt::format("expected a date as YYYY-MM-DD, got \"{}\"", date);
    if (t.year < 1 || t.year > 9999 || !isValidDate(t.year, t.month, t.day))
        return fmt::format("{} is not a date of the calendar", date);
    return std::nullopt;
}

std::optional<std::string> parseTime(const std::string& time, LocalTime& t) {
    char tail = 0;
    int h = 0, m = 0;
    double s = 0;
    const int read = std::sscanf(time.c_str(), "%d:%d:%lf%c", &h, &m, &s, &tail);
    if (read != 2 && read != 3) return fmt::format("expected a time as HH:MM or HH:MM:SS, got \"{}\"", time);
    if (h < 0 || h > 24 || m < 0 || m > 59 || !(s >= 0 && s < 61) || (h == 24 && (m > 0 || s > 0)))
        return fmt::format("{} is not a time of the day", time);
    t.hour = h, t.minute = m, t.second = s;
    return std::nullopt;
}

}  // namespace rayrad::scene
