#include <app/annual/annual_metrics.h>

#include <app/annual/annual_skies.h>
#include <scene/daylight/sun_position.h>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace rayrad::app {

namespace {

/// Day of the week, 0 Sunday … 6 Saturday (from the Julian day number).
int weekday(int year, int month, int day) {
    const long jdn = static_cast<long>(std::floor(scene::julianDay(year, month, day, 12) + 0.5));  // noon: the day's number
    return static_cast<int>((jdn + 1) % 7);
}

/// The day of `month` that is the n-th (1-based; −1 the last) Sunday.
int sunday(int year, int month, int n) {
    static const int kDays[] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
    int last = kDays[month - 1] + (month == 2 && scene::isValidDate(year, 2, 29) ? 1 : 0);
    if (n < 0) {
        for (int d = last; d > 0; --d)
            if (weekday(year, month, d) == 0) return d;
    }
    int seen = 0;
    for (int d = 1; d <= last; ++d)
        if (weekday(year, month, d) == 0 && ++seen == n) return d;
    return last;
}

bool inSummerTime(int year, int month, int day, DaylightSaving s) {
    if (s == DaylightSaving::None) return false;
    const int code = month * 100 + day;
    if (s == DaylightSaving::UnitedStates)
        return code >= 300 + sunday(year, 3, 2) && code < 1100 + sunday(year, 11, 1);
    return code >= 300 + sunday(year, 3, -1) && code < 1000 + sunday(year, 10, -1);
}

}  // namespace

bool isOccupied(int year, int month, int day, double standardClockHour, const Occupancy& o) {
    const double clock = standardClockHour + (inSummerTime(year, month, day, o.saving) ? 1.0 : 0.0);
    return clock >= o.start && clock < o.end;
}

PointYear pointYear(const float* total, const float* sun, const std::vector<char>& occupied,
                    const std::vector<char>& enHours, const AnnualThresholds& t) {
    PointYear p;
    size_t occupiedCount = 0, enCount = 0;
    for (size_t h = 0; h < occupied.size(); ++h) {
        const double e = total[h];
        if (occupied[h]) {
            ++occupiedCount;
            p.da += e >= t.daLux;
            p.cda += std::min(1.0, e / t.daLux);
            p.udiBelow += e < t.udiLow;
            p.udiUseful += e >= t.udiLow && e <= t.udiHigh;
            p.udiAbove += e > t.udiHigh;
            p.sunHours += sun[h] >= t.aseLux;
        }
        if (enHours[h]) {
            ++enCount;
            p.enTarget += e >= t.enTargetLux;
            p.enMinimum += e >= t.enMinimumLux;
        }
    }
    const double n = std::max<size_t>(occupiedCount, 1);
    p.da /= n, p.cda /= n, p.udiBelow /= n, p.udiUseful /= n, p.udiAbove /= n;
    const double m = std::max<size_t>(enCount, 1);
    p.enTarget /= m, p.enMinimum /= m;
    return p;
}

GridYear gridYear(const std::string& grid, const std::vector<const PointYear*>& points, const AnnualThresholds& t) {
    GridYear g;
    g.grid = grid;
    g.points = points.size();
    if (points.empty()) return g;
    for (const PointYear* p : points) {
        g.sda += p->da >= t.daShare;
        g.ase += p->sunHours > t.aseHours;
        g.meanDa += p->da;
        g.meanUdiUseful += p->udiUseful;
        g.enTargetShare += p->enTarget >= 0.5;
        g.enMinimumShare += p->enMinimum >= 0.5;
    }
    const double n = static_cast<double>(points.size());
    g.sda /= n, g.ase /= n, g.meanDa /= n, g.meanUdiUseful /= n, g.enTargetShare /= n, g.enMinimumShare /= n;
    return g;
}

std::vector<char> en17037Hours(const std::vector<SkyHour>& hours) {
    std::vector<size_t> order(hours.size());
    std::iota(order.begin(), order.end(), size_t(0));
    std::stable_sort(order.begin(), order.end(),
                     [&](size_t a, size_t b) { return hours[a].diffuseHorizontal > hours[b].diffuseHorizontal; });
    std::vector<char> chosen(hours.size(), 0);
    for (size_t k = 0; k < std::min<size_t>(4380, order.size()); ++k)
        if (hours[order[k]].diffuseHorizontal > 0) chosen[order[k]] = 1;
    return chosen;
}

}  // namespace rayrad::app
