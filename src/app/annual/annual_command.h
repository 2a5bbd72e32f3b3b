// rayrad annual: read the scene and the weather file, solve the daylight coefficients, run
// the year, print the metrics and write what was asked for.
#pragma once

#include <app/annual/annual_study.h>
#include <app/command_line.h>
#include <scene/daylight/weather_file.h>

#include <optional>
#include <string>

namespace rayrad::app {

/// The sky's direct light is taken on Reinhart's 2 305 patches (MF 4), whatever the solves'.
constexpr int kDirectSkyMultiplication = 4;

int runAnnual(const AnnualArgs& args);

/// "8-18" → 8 … 18 h; throws InputError naming --occupancy.
Occupancy parseOccupancy(const std::string& text, const std::string& saving);

/// The multiplication factor of a sky patch count (145 → 1, 577 → 2, 2305 → 4); throws
/// InputError for any other count.
int patchMultiplicationFactor(int patches);

/// A warning when the weather file's place is far from where the scene places its sun
/// (more than 1° of latitude or longitude apart), or nothing.
std::optional<std::string> weatherPlaceWarning(const scene::WeatherFile& weather, const scene::Daylight& daylight);

/// The per-sensor metrics as CSV: sensor,grid,da_pct,cda_pct,udi_below_pct,udi_useful_pct,
/// udi_above_pct,sun_hours,en17037_target_pct,en17037_minimum_pct,excluded, and with
/// `lampShares` (daylight-linked dimming) lamp_energy_pct (empty where no lamp reaches).
std::string annualMetricsCsv(const std::vector<scene::Sensor>& sensors, const AnnualStudy& study,
                             const std::vector<std::string>& excluded,
                             const std::vector<std::optional<double>>& lampShares = {});

/// The hourly values: one text line "rayrad hourly illuminance 1 points=N hours=H
/// layout=point-major float32-le total-then-sun\n", then N·H float32 of the total
/// illuminance (lx) point after point, then N·H of the direct sun alone.
std::string annualHourlyFile(const AnnualStudy& study);

/// The terminal table: per grid, its points, sDA, ASE, mean DA and UDI, EN 17037.
std::string annualGridTable(const AnnualStudy& study, const AnnualThresholds& t);

}  // namespace rayrad::app
