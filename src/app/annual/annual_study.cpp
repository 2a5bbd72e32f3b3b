#include <app/annual/annual_study.h>

#include <core/input_error.h>
#include <core/stage_report.h>

#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>

namespace rayrad::app {

HourParts hourParts(const DaylightCoefficients& dc, size_t i, const SkyHour& hour, double sunDirect, double k) {
    HourParts parts;
    if (!hour.lit) return parts;
    for (int p = 0; p < dc.patches->count(); ++p)
        parts.skyIndirect += dc.indirectAt(p, i) * hour.patchLuminance[static_cast<size_t>(p)];
    parts.skyIndirect += dc.indirectAt(dc.groundChannel(), i) * hour.groundLuminance;
    const size_t ground = hour.fineLuminance.size();
    for (const auto& [tent, e] : dc.skyDirect.terms[i])
        parts.skyDirect += e * (tent == ground ? hour.groundLuminance : hour.fineLuminance[tent]);
    if (hour.sunNormal > 0) {
        const auto& w = hour.sunWeights;
        for (int j = 0; j < w.count; ++j) parts.sunIndirect += w.weight[j] * dc.sunIndirectAt(w.patch[j], i);
        parts.sunIndirect *= hour.sunNormal * k;
        parts.sunDirect = hour.sunNormal * sunDirect;
    }
    return parts;
}

size_t parseYearHour(const std::string& text, const std::vector<SkyHour>& hours, const std::string& option) {
    int month = 0, day = 0, hour = 0;
    char tail = 0;
    if (std::sscanf(text.c_str(), "%d-%dT%d%c", &month, &day, &hour, &tail) == 3)
        for (size_t h = 0; h < hours.size(); ++h)
            if (hours[h].month == month && hours[h].day == day && std::lround(hours[h].clockHour + 0.5) == hour) return h;
    throw InputError(placeMessage(option, "",
                                  fmt::format("expected MM-DDTHH, an hour of the weather file's year (HH 1 … 24, the "
                                              "hour ending then), got \"{}\"",
                                              text)));
}

AnnualStudy runAnnualStudy(const PipelineRun& run, const DaylightCoefficients& dc, const SunLight& sunLight,
                           const std::vector<SkyHour>& hours, const Occupancy& occupancy,
                           const AnnualThresholds& thresholds, const std::vector<std::string>& excluded, int year) {
    const auto start = std::chrono::steady_clock::now();
    const double cpuStart = processCpuSeconds();
    AnnualStudy s;
    s.points = dc.points;
    s.hours = hours.size();
    std::vector<char>& occupied = s.occupied;
    occupied.assign(hours.size(), 0);
    for (size_t h = 0; h < hours.size(); ++h) {
        occupied[h] = isOccupied(year, hours[h].month, hours[h].day, hours[h].clockHour, occupancy);
        s.occupiedHours += occupied[h];
        s.litHours += hours[h].lit;
    }
    if (s.occupiedHours == 0)
        throw InputError(placeMessage("--occupancy", "",
                                      fmt::format("the schedule {}–{} h takes no hour of the year", occupancy.start,
                                                  occupancy.end)));
    const std::vector<char> enHours = en17037Hours(hours);
    for (char c : enHours) s.en17037HourCount += c;

    s.total.assign(s.points * s.hours, 0.0f);
    s.sun.assign(s.points * s.hours, 0.0f);
    s.pointYears.resize(s.points);
    std::vector<double> sunScale(hours.size(), 0.0);
    tbb::parallel_for(size_t(0), hours.size(), [&](size_t h) {
        if (hours[h].sunNormal > 0) sunScale[h] = sunLight.sunScale(hours[h].toSun, hours[h].sunWeights);
    });
    tbb::parallel_for(size_t(0), s.points, [&](size_t i) {
        const scene::Sensor& sensor = run.scene.sensors[i];
        float* total = &s.total[i * s.hours];
        float* sun = &s.sun[i * s.hours];
        for (size_t h = 0; h < s.hours; ++h) {
            const SkyHour& hour = hours[h];
            if (!hour.lit) continue;
            const double direct =
                hour.sunNormal > 0 ? sunLight.directAt(sensor.position, sensor.normal, hour.toSun) : 0.0;
            total[h] = static_cast<float>(hourParts(dc, i, hour, direct, sunScale[h]).total());
            sun[h] = static_cast<float>(hour.sunNormal * direct);
        }
        s.pointYears[i] = pointYear(total, sun, occupied, enHours, thresholds);
    });

    // The grids, in the order they first appear; points that are no measurement left out.
    std::vector<std::string> order;
    std::map<std::string, std::vector<const PointYear*>> members;
    for (size_t i = 0; i < s.points; ++i) {
        const std::string& grid = run.scene.sensors[i].grid;
        if (grid.empty()) continue;
        if (!members.count(grid)) order.push_back(grid);
        auto& list = members[grid];
        if (i >= excluded.size() || excluded[i].empty()) list.push_back(&s.pointYears[i]);
    }
    for (const auto& g : order) s.grids.push_back(gridYear(g, members[g], thresholds));
    s.cpuSeconds = processCpuSeconds() - cpuStart;
    s.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return s;
}

}  // namespace rayrad::app
