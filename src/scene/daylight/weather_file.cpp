#include <scene/daylight/weather_file.h>

#include <core/input_error.h>
#include <core/input_file.h>

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <sstream>

namespace rayrad::scene {

namespace {

std::vector<std::string> splitFields(const std::string& line) {
    std::vector<std::string> out;
    std::string field;
    std::istringstream in(line);
    while (std::getline(in, field, ',')) out.push_back(field);
    if (!line.empty() && line.back() == ',') out.emplace_back();
    return out;
}

std::string trimmed(std::string s) {
    while (!s.empty() && (s.back() == '\r' || s.back() == ' ' || s.back() == '\t')) s.pop_back();
    size_t i = 0;
    while (i < s.size() && (s[i] == ' ' || s[i] == '\t')) ++i;
    return s.substr(i);
}

class Reader {
  public:
    Reader(const std::string& path, size_t line) : m_path(path), m_line(line) {}
    [[noreturn]] void fail(const std::string& what) const {
        throw InputError(placeMessage(m_path, fmt::format("line {}", m_line), what));
    }
    double number(const std::vector<std::string>& f, size_t i, const char* name) const {
        if (i >= f.size()) fail(fmt::format("field {} ({}) is missing", i + 1, name));
        const std::string s = trimmed(f[i]);
        char* end = nullptr;
        const double v = std::strtod(s.c_str(), &end);
        if (s.empty() || *end != '\0' || !std::isfinite(v))
            fail(fmt::format("field {} ({}): expected a number, got \"{}\"", i + 1, name, s));
        return v;
    }
    /// A light value: EPW writes 9999 (irradiance) or 999999 (illuminance) where it is
    /// missing; the annual study needs every hour's.
    double light(const std::vector<std::string>& f, size_t i, const char* name, double missing, double most) const {
        const double v = number(f, i, name);
        if (v >= missing) fail(fmt::format("field {} ({}) is missing ({}): every hour's light is needed", i + 1, name, v));
        if (v < 0 || v > most)
            fail(fmt::format("field {} ({}): expected 0 … {}, got {}", i + 1, name, most, v));
        return v;
    }

  private:
    const std::string& m_path;
    size_t m_line;
};

}  // namespace

WeatherFile parseWeatherFile(const std::string& text, const std::string& path) {
    WeatherFile w;
    w.path = path;
    std::istringstream in(text);
    std::string line;
    size_t number = 0;
    bool inData = false;
    while (std::getline(in, line)) {
        ++number;
        line = trimmed(line);
        if (line.empty()) continue;
        Reader r(path, number);
        const auto f = splitFields(line);
        if (number == 1) {
            if (f.empty() || trimmed(f[0]) != "LOCATION")
                r.fail("not an EnergyPlus weather file (EPW): its first line must begin with LOCATION");
            w.city = f.size() > 1 ? trimmed(f[1]) : "";
            w.region = f.size() > 2 ? trimmed(f[2]) : "";
            w.country = f.size() > 3 ? trimmed(f[3]) : "";
            w.source = f.size() > 4 ? trimmed(f[4]) : "";
            w.latitudeDeg = r.number(f, 6, "latitude");
            w.longitudeDeg = r.number(f, 7, "longitude");
            w.timeZoneHours = r.number(f, 8, "time zone");
            w.elevationM = r.number(f, 9, "elevation");
            if (std::abs(w.latitudeDeg) > 90) r.fail(fmt::format("latitude {}° is beyond ±90°", w.latitudeDeg));
            if (std::abs(w.longitudeDeg) > 180) r.fail(fmt::format("longitude {}° is beyond ±180°", w.longitudeDeg));
            if (std::abs(w.timeZoneHours) > 14) r.fail(fmt::format("time zone {} h is beyond ±14 h", w.timeZoneHours));
            continue;
        }
        if (!inData) {
            inData = trimmed(f[0]) == "DATA PERIODS";
            continue;
        }
        if (f.size() < 35)
            r.fail(fmt::format("an hour has 35 fields, this line {} (a truncated or damaged file?)", f.size()));
        WeatherHour h;
        h.month = static_cast<int>(r.number(f, 1, "month"));
        h.day = static_cast<int>(r.number(f, 2, "day"));
        h.hour = static_cast<int>(r.number(f, 3, "hour"));
        if (h.month < 1 || h.month > 12 || h.day < 1 || h.day > 31 || h.hour < 1 || h.hour > 24)
            r.fail(fmt::format("month {}, day {}, hour {} is not a time of the year", h.month, h.day, h.hour));
        const double dew = r.number(f, 7, "dew point");
        h.dewPointC = dew < 99 && dew > -90 ? dew : 11.0;  // 99.9: missing; the Perez model's typical value
        // Direct normal irradiance reaches at most the solar constant (1 361 W/m²).
        h.directNormalIrradiance = r.light(f, 14, "direct normal radiation", 9999, 1400);
        h.diffuseHorizontalIrradiance = r.light(f, 15, "diffuse horizontal radiation", 9999, 1400);
        h.directNormalIlluminance = r.light(f, 17, "direct normal illuminance", 999900, 160000);
        h.diffuseHorizontalIlluminance = r.light(f, 18, "diffuse horizontal illuminance", 999900, 160000);
        if (!w.hours.empty()) {
            const WeatherHour& p = w.hours.back();
            const bool next = (h.month == p.month && h.day == p.day && h.hour == p.hour + 1) ||
                              (p.hour == 24 && h.hour == 1 &&
                               ((h.month == p.month && h.day == p.day + 1) || (h.month == p.month + 1 && h.day == 1)));
            if (!next)
                r.fail(fmt::format("hour {} of {}/{} does not follow hour {} of {}/{} (hours missing or out of order)",
                                   h.hour, h.month, h.day, p.hour, p.month, p.day));
        } else if (h.month != 1 || h.day != 1 || h.hour != 1) {
            r.fail(fmt::format("the year must begin with hour 1 of 1/1, not hour {} of {}/{}", h.hour, h.month, h.day));
        }
        w.hours.push_back(h);
    }
    if (number == 0) throw InputError(placeMessage(path, "", "the weather file is empty"));
    if (!inData) throw InputError(placeMessage(path, "", "no DATA PERIODS line: not a whole EPW file"));
    if (w.hours.size() != 8760 && w.hours.size() != 8784)
        throw InputError(placeMessage(path, "",
                                      fmt::format("{} hours: a weather file holds a whole year, 8 760 hours (8 784 "
                                                  "with 29 February); the file may be cut short",
                                                  w.hours.size())));
    return w;
}

WeatherFile readWeatherFile(const std::string& path) {
    checkInputFile(path, "weather file");
    return parseWeatherFile(readInputFile(path, "weather file", size_t(64) << 20), path);
}

}  // namespace rayrad::scene
