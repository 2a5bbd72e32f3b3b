#include <app/grid_statistics.h>

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <limits>

namespace rayrad::app {

std::vector<GridStatistics> gridStatistics(const std::vector<SensorResult>& results) {
    std::vector<GridStatistics> out;
    for (const auto& r : results) {
        if (r.sensor.grid.empty()) continue;
        auto it =
            std::find_if(out.begin(), out.end(), [&](const GridStatistics& g) { return g.grid == r.sensor.grid; });
        if (it == out.end()) {
            out.push_back({r.sensor.grid, 0, 0, std::numeric_limits<double>::infinity(), 0, 0});
            it = out.end() - 1;
        }
        if (!r.excluded.empty()) {
            ++it->excluded;
            continue;
        }
        const double e = luminance(r.value.direct + r.value.indirect);
        ++it->points;
        it->minimum = std::min(it->minimum, e);
        it->maximum = std::max(it->maximum, e);
        it->mean += e;
    }
    for (auto& g : out) {
        if (g.points == 0)
            g.minimum = 0;
        else
            g.mean /= static_cast<double>(g.points);
    }
    return out;
}

std::string gridTable(const std::vector<GridStatistics>& grids) {
    if (grids.empty()) return "";
    std::string s = fmt::format("{:<14} {:>7} {:>11} {:>11} {:>11} {:>8} {:>10}\n", "grid", "points", "Emin lx",
                                "Eavg lx", "Emax lx", "U0", "Emin/Emax");
    for (const auto& g : grids)
        s += fmt::format("{:<14} {:>7} {:>11.2f} {:>11.2f} {:>11.2f} {:>8.3f} {:>10.3f}{}\n", g.grid, g.points,
                         g.minimum, g.mean, g.maximum, g.u0(), g.minToMax(),
                         g.excluded ? fmt::format("  ({} more inside solids, left out)", g.excluded) : "");
    return s;
}

std::string gridCsv(const std::vector<GridStatistics>& grids) {
    std::string s = "grid,points,emin_lx,eavg_lx,emax_lx,u0,emin_emax,excluded_points\n";
    for (const auto& g : grids)
        s += fmt::format("{},{},{:.9g},{:.9g},{:.9g},{:.6f},{:.6f},{}\n", csvField(g.grid), g.points, g.minimum, g.mean,
                         g.maximum, g.u0(), g.minToMax(), g.excluded);
    return s;
}

std::string gridSummaryPath(const std::string& sensorCsvPath) {
    const std::filesystem::path p(sensorCsvPath);
    return (p.parent_path() / (p.stem().string() + ".grids" + p.extension().string())).string();
}

}  // namespace rayrad::app
