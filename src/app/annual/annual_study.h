// A year of daylight at every sensor from the daylight coefficients: each hour's
// illuminance is a weighted sum of the coefficients, the sun's direct light traced apart.
#pragma once

#include <app/annual/annual_metrics.h>
#include <app/annual/annual_skies.h>
#include <app/annual/daylight_coefficients.h>
#include <app/annual/sun_light.h>

#include <string>
#include <vector>

namespace rayrad::app {

/// Point i's illuminance (lx) in one hour, by part:
///   E = Σ_f D_f L_f  +  Σ_c I_c L_c  +  k E_n Σ_j w_j S_j  +  E_n · sunDirect,
/// the sky's direct light over the fine tents f (L_f the sky's luminance at their centres)
/// and the ground, its interreflected light over the solves' channels c (L_c the sky's
/// tent-weighted mean luminance; the ground); the sun's interreflected
/// light interpolated between the suns S_j at the centres of the patches around it
/// (weights w_j), scaled by k (SunLight::sunScale) to bring in what the sun itself does;
/// its direct light exact (`sunDirect`: cosθ τ V toward the sun, SunLight::directAt).
struct HourParts {
    double skyDirect = 0, skyIndirect = 0, sunIndirect = 0, sunDirect = 0;
    double total() const { return skyDirect + skyIndirect + sunIndirect + sunDirect; }
};
HourParts hourParts(const DaylightCoefficients& dc, size_t i, const SkyHour& hour, double sunDirect, double k);

/// The hour of the year (0-based) of "MM-DDTHH" (the weather file's hour ending at HH:00),
/// or an InputError naming `option`.
size_t parseYearHour(const std::string& text, const std::vector<SkyHour>& hours, const std::string& option = "--hour");

struct AnnualStudy {
    size_t points = 0, hours = 0;
    /// Point-major: [i · hours + h], lx. The total, and the direct sun alone (LM-83's ASE).
    std::vector<float> total, sun;
    std::vector<PointYear> pointYears;
    std::vector<GridYear> grids;
    std::vector<char> occupied;  ///< per hour
    int occupiedHours = 0, litHours = 0, en17037HourCount = 0;
    double cpuSeconds = 0, wallSeconds = 0;
};

/// Every hour at every sensor of `run`, and the metrics; `excluded` per sensor (inside a
/// solid, buried: left out of the grids' shares, as in grid statistics). `year` places
/// the occupancy's summer time. Throws InputError when the schedule takes no hour.
AnnualStudy runAnnualStudy(const PipelineRun& run, const DaylightCoefficients& dc, const SunLight& sunLight,
                           const std::vector<SkyHour>& hours, const Occupancy& occupancy, const AnnualThresholds& thresholds,
                           const std::vector<std::string>& excluded, int year);

}  // namespace rayrad::app
