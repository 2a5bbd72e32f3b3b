// An EnergyPlus weather file (EPW): the place and a year of hourly sunlight.
#pragma once

#include <string>
#include <vector>

namespace rayrad::scene {

/// One hour of a weather file: the hour ending at `hour`:00 local standard time (EPW's
/// hours run 1 … 24, the light of the hour before), and what was measured or modelled.
struct WeatherHour {
    int month = 1, day = 1, hour = 1;
    double dewPointC = 11;
    double directNormalIrradiance = 0;       ///< W/m² (EPW field 15, Wh/m² over the hour)
    double diffuseHorizontalIrradiance = 0;  ///< W/m² (field 16)
    double directNormalIlluminance = 0;      ///< lx (field 18)
    double diffuseHorizontalIlluminance = 0; ///< lx (field 19)
};

struct WeatherFile {
    std::string path;
    std::string city, region, country, source;
    double latitudeDeg = 0, longitudeDeg = 0;  ///< north, east positive
    double timeZoneHours = 0;                  ///< standard time − UTC, h
    double elevationM = 0;
    std::vector<WeatherHour> hours;  ///< 8 760 (8 784 with 29 February)
};

/// Reads an EPW file: its LOCATION line, then after the DATA PERIODS line one line of 35
/// fields per hour. Throws InputError naming the file, the line and the field for anything
/// that is not a whole year of sane hours (a truncated or corrupted file, a place off the
/// globe, a missing value where the sun's light should be).
WeatherFile readWeatherFile(const std::string& path);

/// The same from the file's text (`path` for messages).
WeatherFile parseWeatherFile(const std::string& text, const std::string& path);

}  // namespace rayrad::scene
