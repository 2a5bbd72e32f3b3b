// Where the sun is: its altitude and azimuth seen from a place on the Earth at a local time.
#pragma once

#include <optional>
#include <string>

namespace rayrad::scene {

/// A civil date and time at a place: the clock's reading and its offset from UTC.
struct LocalTime {
    int year = 2000, month = 1, day = 1;
    int hour = 12, minute = 0;
    double second = 0;
    double utcOffsetHours = 0;  ///< local time − UTC, h (Central Europe in winter +1, Denver −7)
};

/// A place on the Earth and the air the sun is seen through (for refraction).
struct Site {
    double latitudeDeg = 0;   ///< north positive, [−90, 90]
    double longitudeDeg = 0;  ///< east positive, [−180, 180]
    double elevationM = 0;    ///< above sea level, m (for the parallax of the sun; tiny)
    double pressureMbar = 1010;
    double temperatureC = 10;
    double deltaTSeconds = 69;  ///< TT − UT, s (69 around 2020; 64 in 2000)
};

/// The sun seen from a site, in degrees: altitude above the horizon (refracted, topocentric)
/// and azimuth from north toward east (180 south).
struct SunPosition {
    double altitudeDeg = 0;
    double azimuthDeg = 0;
    double zenithDeg() const { return 90 - altitudeDeg; }
};

/// The sun's position after Meeus (Astronomical Algorithms, 2nd ed., chapters 7, 12, 13, 22
/// and 25): the sun's apparent longitude from its mean longitude, mean anomaly and equation
/// of the centre (good to 0.01° in longitude), nutation and aberration, apparent sidereal
/// time, the topocentric parallax and the atmospheric refraction of Bennett's formula as
/// NREL's Solar Position Algorithm applies it. The test suite checks it against the SPA
/// paper's worked example (within 0.01°).
SunPosition sunPosition(const LocalTime& time, const Site& site);

/// Julian day number (days, with fraction) of a UTC calendar date and time, Meeus ch. 7
/// (Gregorian calendar).
double julianDay(int year, int month, int day, double hourUtc);

/// Whether year-month-day is a date of the Gregorian calendar (29 February in leap years).
bool isValidDate(int year, int month, int day);

/// "YYYY-MM-DD" into `t`; an error message, or nothing when it reads.
std::optional<std::string> parseDate(const std::string& date, LocalTime& t);
/// "HH:MM" or "HH:MM:SS" into `t`; an error message, or nothing when it reads.
std::optional<std::string> parseTime(const std::string& time, LocalTime& t);

}  // namespace rayrad::scene
