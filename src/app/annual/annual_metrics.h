// Climate-based daylight metrics from a year of hourly illuminance: daylight autonomy (DA,
// cDA), spatial daylight autonomy (sDA) and annual sunlight exposure (ASE) as IES LM-83
// defines them, useful daylight illuminance (UDI), and EN 17037's target and minimum levels.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace rayrad::app {

struct SkyHour;

/// Summer time: none, the United States' (second Sunday of March to the first Sunday of
/// November) or the European Union's (last Sunday of March to the last Sunday of October).
enum class DaylightSaving { None, UnitedStates, Europe };

/// The hours the space is used, on the clock (summer time included): every day of the
/// year from `start` to `end` h (LM-83: 8:00 to 18:00).
struct Occupancy {
    double start = 8, end = 18;
    DaylightSaving saving = DaylightSaving::None;
};

/// Whether the hour (its middle on the local standard clock, month and day of `year`)
/// is occupied.
bool isOccupied(int year, int month, int day, double standardClockHour, const Occupancy& o);

/// The thresholds (LM-83 and common UDI bands; EN 17037's minimum level).
struct AnnualThresholds {
    double daLux = 300, daShare = 0.5;          ///< DA300, sDA300/50%
    double aseLux = 1000, aseHours = 250;       ///< ASE1000,250h (direct sun only)
    double udiLow = 100, udiHigh = 3000;        ///< UDI bands: below, between, above
    double enTargetLux = 300, enMinimumLux = 100;  ///< EN 17037 minimum level, over half the daylight hours
};

/// One point's year.
struct PointYear {
    double da = 0;   ///< share of occupied hours with E ≥ daLux
    double cda = 0;  ///< mean over occupied hours of min(1, E / daLux)
    double udiBelow = 0, udiUseful = 0, udiAbove = 0;  ///< shares of occupied hours
    int sunHours = 0;                ///< occupied hours with direct sun alone ≥ aseLux
    double enTarget = 0, enMinimum = 0;  ///< shares of EN 17037's daylight hours with E ≥ 300 / 100 lx
};

/// A point's metrics from its hourly total illuminance and direct sun (lx, one value per
/// hour), `occupied` and `enHours` flags per hour.
PointYear pointYear(const float* total, const float* sun, const std::vector<char>& occupied,
                    const std::vector<char>& enHours, const AnnualThresholds& t);

/// A grid's: its points weighted alike (equal cells).
struct GridYear {
    std::string grid;
    size_t points = 0;
    double sda = 0;       ///< share of points with DA ≥ daShare
    double ase = 0;       ///< share of points with more than aseHours sun hours
    double meanDa = 0, meanUdiUseful = 0;
    double enTargetShare = 0, enMinimumShare = 0;  ///< shares of points reaching the level for half the hours
    bool meetsEn17037Minimum() const { return enTargetShare >= 0.5 && enMinimumShare >= 0.95; }
};
GridYear gridYear(const std::string& grid, const std::vector<const PointYear*>& points, const AnnualThresholds& t);

/// EN 17037's daylight hours: the half of the year's hours with the most diffuse daylight
/// (the 4 380 brightest E_dh), as climate-based EN 17037 studies take them.
std::vector<char> en17037Hours(const std::vector<SkyHour>& hours);

}  // namespace rayrad::app
