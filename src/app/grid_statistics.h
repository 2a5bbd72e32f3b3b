// What a lighting designer reads off a calculation grid: the minimum, mean and maximum
// illuminance and the uniformities (EN 12464-1: U0 = Emin / Eavg; also Emin / Emax).
#pragma once

#include <app/sensor_table.h>

#include <optional>
#include <string>
#include <vector>

namespace rayrad::app {

struct GridStatistics {
    std::string grid;
    size_t points = 0;    ///< the points the figures are of
    size_t excluded = 0;  ///< points inside a solid or buried (SensorResult::excluded), not counted
    double minimum = 0, mean = 0, maximum = 0;                               ///< total illuminance Y, lx
    double median = 0;                                                       ///< lx
    /// Under a sky without sun: the daylight factors' minimum, mean and median, %.
    std::optional<double> dfMinimum, dfMean, dfMedian;
    /// EN 17037 method 1 (with the site's median external diffuse illuminance E): the
    /// targets D_T = 100 · 300 / E and D_TM = 100 · 100 / E (%), and the shares of points
    /// whose daylight factor reaches them (the minimum level asks 50 % and 95 %).
    std::optional<double> dfTarget, dfTargetMinimum, shareAboveTarget, shareAboveTargetMinimum;
    bool meetsEn17037Minimum() const {
        return shareAboveTarget && *shareAboveTarget >= 0.5 && *shareAboveTargetMinimum >= 0.95;
    }
    double u0() const { return mean > 0 ? minimum / mean : 0; }              ///< Emin / Eavg
    double minToMax() const { return maximum > 0 ? minimum / maximum : 0; }  ///< Emin / Emax
};

/// One entry per sensor grid, in the order the grids appear; the total illuminance
/// (direct + gathered indirect) of each point, every point weighted alike (the points
/// are cell centres of equal cells). Points inside a solid are no measurement: counted
/// apart, not in the figures (a grid with no other point has none: 0).
std::vector<GridStatistics> gridStatistics(const std::vector<SensorResult>& results,
                                           std::optional<double> medianExternalIlluminance = std::nullopt);

/// An aligned text table for the terminal.
std::string gridTable(const std::vector<GridStatistics>& grids);

/// CSV: grid,points,emin_lx,eavg_lx,emax_lx,u0,emin_emax,excluded_points.
std::string gridCsv(const std::vector<GridStatistics>& grids);

/// The summary file beside a sensor CSV: "out/room.csv" → "out/room.grids.csv".
std::string gridSummaryPath(const std::string& sensorCsvPath);

}  // namespace rayrad::app
