// The annual metrics on hand-made years whose answers are known, and the occupancy clock.
#include <app/annual/annual_command.h>
#include <app/annual/annual_metrics.h>
#include <app/annual/annual_skies.h>
#include <core/input_error.h>

#include "test_support.h"

#include <vector>

using namespace rayrad;
using namespace rayrad::app;

namespace {

/// A year of 8 760 hours, 1 January 2021 on; `f(day, clockHour)` the value of each.
template <class F>
std::vector<float> year(F&& f) {
    std::vector<float> v(8760);
    for (size_t h = 0; h < v.size(); ++h) v[h] = static_cast<float>(f(static_cast<int>(h / 24), h % 24 + 0.5));
    return v;
}

/// The hours of 2021 as SkyHours (their month, day and clock hour).
std::vector<SkyHour> hoursOf2021() {
    static const int kDays[] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
    std::vector<SkyHour> hours;
    for (int m = 1; m <= 12; ++m)
        for (int d = 1; d <= kDays[m - 1]; ++d)
            for (int h = 1; h <= 24; ++h) {
                SkyHour s;
                s.month = m, s.day = d, s.clockHour = h - 0.5;
                hours.push_back(s);
            }
    return hours;
}

std::vector<char> occupiedOf(const std::vector<SkyHour>& hours, const Occupancy& o) {
    std::vector<char> v;
    for (const auto& h : hours) v.push_back(isOccupied(2021, h.month, h.day, h.clockHour, o));
    return v;
}

}  // namespace

TEST_CASE("annual: the occupancy clock, with and without summer time", "[annual]") {
    const auto hours = hoursOf2021();
    for (auto saving : {DaylightSaving::None, DaylightSaving::UnitedStates, DaylightSaving::Europe}) {
        size_t n = 0;
        for (char c : occupiedOf(hours, {8, 18, saving})) n += c;
        CHECK(n == 3650);  // ten hours every day, whatever the clock
    }
    // 2021: US summer time from Sunday 14 March, the EU's from Sunday 28 March.
    const Occupancy us{8, 18, DaylightSaving::UnitedStates}, eu{8, 18, DaylightSaving::Europe};
    CHECK_FALSE(isOccupied(2021, 3, 13, 7.5, us));
    CHECK(isOccupied(2021, 3, 14, 7.5, us));  // 7:30 standard is 8:30 on the clock
    CHECK_FALSE(isOccupied(2021, 3, 27, 7.5, eu));
    CHECK(isOccupied(2021, 3, 28, 7.5, eu));
    CHECK(isOccupied(2021, 10, 30, 7.5, eu));
    CHECK_FALSE(isOccupied(2021, 10, 31, 7.5, eu));
    CHECK(isOccupied(2021, 11, 6, 7.5, us));
    CHECK_FALSE(isOccupied(2021, 11, 7, 7.5, us));
    CHECK_THROWS_AS(parseOccupancy("18-8", "none"), InputError);
    CHECK_THROWS_AS(parseOccupancy("8-18", "mars"), InputError);
    CHECK(parseOccupancy("7.5-17", "eu").start == 7.5);
}

TEST_CASE("annual: DA, cDA, UDI, sun hours and EN 17037 on hand-made years", "[annual]") {
    const auto hours = hoursOf2021();
    const auto occupied = occupiedOf(hours, {8, 18, DaylightSaving::None});
    // EN 17037's hours here: the first 4 380 hours of the year.
    std::vector<char> en(8760, 0);
    for (size_t h = 0; h < 4380; ++h) en[h] = 1;
    const AnnualThresholds t;

    // 400 lx in the mornings (8–13 h), 50 lx in the afternoons: DA = cDA-part 50 %.
    const auto total = year([](int, double clock) { return clock < 13 ? 400.0 : 50.0; });
    const auto sun = year([](int day, double clock) { return day < 30 && clock > 8 && clock < 12 ? 5000.0 : 0.0; });
    const PointYear p = pointYear(total.data(), sun.data(), occupied, en, t);
    CHECK(p.da == Approx(0.5));
    CHECK(p.cda == Approx(0.5 + 0.5 * 50.0 / 300));
    CHECK(p.udiBelow == Approx(0.5));
    CHECK(p.udiUseful == Approx(0.5));
    CHECK(p.udiAbove == 0);
    CHECK(p.sunHours == 30 * 4);  // 8:30 … 11:30 on 30 days
    // 0:30 … 12:30 of each day at 400 lx: 182 whole days and the first twelve hours of the next.
    CHECK(p.enTarget == Approx((182 * 13 + 12) / 4380.0));
    CHECK(p.enMinimum == Approx((182 * 13 + 12) / 4380.0));

    // A grid of four such points, two of them brighter: sDA, ASE and EN 17037's shares.
    const auto bright = year([](int, double) { return 5000.0; });
    const auto sunny = year([](int, double clock) { return clock > 8 && clock < 18 ? 2000.0 : 0.0; });
    const PointYear q = pointYear(bright.data(), sunny.data(), occupied, en, t);
    CHECK(q.udiAbove == 1);
    CHECK(q.sunHours == 3650);
    const auto dim = year([](int, double) { return 50.0; });
    const auto none = year([](int, double) { return 0.0; });
    const PointYear d = pointYear(dim.data(), none.data(), occupied, en, t);
    const GridYear g = gridYear("plane", {&p, &d, &q, &q}, t);
    CHECK(g.sda == Approx(0.75));  // DA ≥ 50 %: p (just) and q
    CHECK(g.ase == Approx(0.5));   // more than 250 h: q only
    CHECK(g.enTargetShare == Approx(0.75));
    CHECK(g.enMinimumShare == Approx(0.75));
    CHECK_FALSE(g.meetsEn17037Minimum());  // 95 % asked at 100 lx
    CHECK(gridYear("plane", {&p, &q}, t).meetsEn17037Minimum());
}

TEST_CASE("annual: EN 17037's hours are the half of the year with the most diffuse light", "[annual]") {
    auto hours = hoursOf2021();
    for (size_t h = 0; h < hours.size(); ++h) hours[h].diffuseHorizontal = static_cast<double>(h % 24 == 12 ? 1e4 : h % 7);
    const auto en = en17037Hours(hours);
    size_t n = 0, noon = 0;
    for (size_t h = 0; h < en.size(); ++h) n += en[h], noon += en[h] && h % 24 == 12;
    CHECK(n == 4380);
    CHECK(noon == 365);
}

TEST_CASE("annual: sky patch counts and the weather file's place against the scene's", "[annual]") {
    CHECK(patchMultiplicationFactor(145) == 1);
    CHECK(patchMultiplicationFactor(577) == 2);
    CHECK(patchMultiplicationFactor(2305) == 4);
    CHECK_THROWS_AS(patchMultiplicationFactor(100), InputError);
    scene::WeatherFile w;
    w.city = "Chicago";
    w.latitudeDeg = 41.98, w.longitudeDeg = -87.92;
    scene::Daylight d;
    CHECK_FALSE(weatherPlaceWarning(w, d));  // the scene gives no place
    d.site = scene::Site{};
    d.site->latitudeDeg = 42.3, d.site->longitudeDeg = -87.6;
    CHECK_FALSE(weatherPlaceWarning(w, d));
    d.site->latitudeDeg = 48.1, d.site->longitudeDeg = 11.6;  // Munich
    const auto warning = weatherPlaceWarning(w, d);
    REQUIRE(warning);
    CHECK(warning->find("Chicago") != std::string::npos);
}
