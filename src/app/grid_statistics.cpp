#include <app/grid_statistics.h>

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <limits>

namespace rayrad::app {

namespace {
/// The median of `v` (reordered), 0 when empty.
double median(std::vector<double>& v) {
    if (v.empty()) return 0;
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}
}  // namespace

std::vector<GridStatistics> gridStatistics(const std::vector<SensorResult>& results,
                                           std::optional<double> medianExternalIlluminance) {
    std::vector<GridStatistics> out;
    std::vector<std::vector<double>> values, factors;  // per grid
    for (const auto& r : results) {
        if (r.sensor.grid.empty()) continue;
        auto it =
            std::find_if(out.begin(), out.end(), [&](const GridStatistics& g) { return g.grid == r.sensor.grid; });
        if (it == out.end()) {
            GridStatistics g;
            g.grid = r.sensor.grid;
            g.minimum = std::numeric_limits<double>::infinity();
            out.push_back(g);
            values.emplace_back();
            factors.emplace_back();
            it = out.end() - 1;
        }
        const auto g = static_cast<size_t>(it - out.begin());
        if (!r.excluded.empty()) {
            ++it->excluded;
            continue;
        }
        const double e = luminance(r.value.direct + r.value.indirect);
        ++it->points;
        it->minimum = std::min(it->minimum, e);
        it->maximum = std::max(it->maximum, e);
        it->mean += e;
        values[g].push_back(e);
        if (r.daylightFactor) factors[g].push_back(*r.daylightFactor);
    }
    for (size_t k = 0; k < out.size(); ++k) {
        GridStatistics& g = out[k];
        if (g.points == 0)
            g.minimum = 0;
        else
            g.mean /= static_cast<double>(g.points);
        g.median = median(values[k]);
        if (!factors[k].empty() && factors[k].size() == g.points) {
            g.dfMinimum = *std::min_element(factors[k].begin(), factors[k].end());
            double sum = 0;
            for (double f : factors[k]) sum += f;
            g.dfMean = sum / static_cast<double>(factors[k].size());
            g.dfMedian = median(factors[k]);
            if (medianExternalIlluminance && *medianExternalIlluminance > 0) {
                g.dfTarget = 100 * 300 / *medianExternalIlluminance;
                g.dfTargetMinimum = 100 * 100 / *medianExternalIlluminance;
                size_t above = 0, aboveMinimum = 0;
                for (double f : factors[k]) above += f >= *g.dfTarget, aboveMinimum += f >= *g.dfTargetMinimum;
                g.shareAboveTarget = above / static_cast<double>(factors[k].size());
                g.shareAboveTargetMinimum = aboveMinimum / static_cast<double>(factors[k].size());
            }
        }
    }
    return out;
}

std::string gridTable(const std::vector<GridStatistics>& grids) {
    if (grids.empty()) return "";
    std::string s = fmt::format("{:<14} {:>7} {:>11} {:>11} {:>11} {:>11} {:>8} {:>10}\n", "grid", "points",
                                "Emin lx", "Eavg lx", "Emedian lx", "Emax lx", "U0", "Emin/Emax");
    for (const auto& g : grids)
        s += fmt::format("{:<14} {:>7} {:>11.2f} {:>11.2f} {:>11.2f} {:>11.2f} {:>8.3f} {:>10.3f}{}\n", g.grid,
                         g.points, g.minimum, g.mean, g.median, g.maximum, g.u0(), g.minToMax(),
                         g.excluded ? fmt::format("  ({} more inside solids, left out)", g.excluded) : "");
    bool factors = false;
    for (const auto& g : grids) factors |= g.dfMean.has_value();
    if (!factors) return s;
    s += fmt::format("{:<14} {:>9} {:>9} {:>11} {:>8}\n", "daylight", "DFmin %", "DFavg %", "DFmedian %", "U0");
    for (const auto& g : grids)
        if (g.dfMean)
            s += fmt::format("{:<14} {:>9.2f} {:>9.2f} {:>11.2f} {:>8.3f}\n", g.grid, *g.dfMinimum, *g.dfMean,
                             *g.dfMedian, *g.dfMean > 0 ? *g.dfMinimum / *g.dfMean : 0.0);
    for (const auto& g : grids)
        if (g.shareAboveTarget)
            s += fmt::format("EN 17037 method 1, {}: DF ≥ D_T {:.2f} % on {:.0f} % of points (50 % asked), DF ≥ D_TM "
                             "{:.2f} % on {:.0f} % (95 % asked): the minimum level is {}\n",
                             g.grid, *g.dfTarget, 100 * *g.shareAboveTarget, *g.dfTargetMinimum,
                             100 * *g.shareAboveTargetMinimum, g.meetsEn17037Minimum() ? "met" : "not met");
    return s;
}

std::string gridCsv(const std::vector<GridStatistics>& grids) {
    std::string s = "grid,points,emin_lx,eavg_lx,emax_lx,u0,emin_emax,excluded_points,emedian_lx,"
                    "df_min_pct,df_mean_pct,df_median_pct\n";
    auto cell = [](const std::optional<double>& v) { return v ? fmt::format("{:.6f}", *v) : std::string(); };
    for (const auto& g : grids)
        s += fmt::format("{},{},{:.9g},{:.9g},{:.9g},{:.6f},{:.6f},{},{:.9g},{},{},{}\n", csvField(g.grid), g.points,
                         g.minimum, g.mean, g.maximum, g.u0(), g.minToMax(), g.excluded, g.median, cell(g.dfMinimum),
                         cell(g.dfMean), cell(g.dfMedian));
    return s;
}

std::string gridSummaryPath(const std::string& sensorCsvPath) {
    const std::filesystem::path p(sensorCsvPath);
    return (p.parent_path() / (p.stem().string() + ".grids" + p.extension().string())).string();
}

}  // namespace rayrad::app
