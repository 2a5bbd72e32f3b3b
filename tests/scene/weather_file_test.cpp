// The EnergyPlus weather file reader: a real file, and broken ones.
#include <core/input_error.h>
#include <scene/daylight/weather_file.h>

#include "test_support.h"

#include <fstream>
#include <sstream>

using namespace rayrad;

namespace {

const char* kChicago = "scenes/weather/USA_IL_Chicago-OHare.Intl.AP.725300_TMY3.epw";

std::string chicagoText() {
    std::ifstream in(test::sourcePath(kChicago));
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

std::string refused(const std::string& text) {
    try {
        scene::parseWeatherFile(text, "w.epw");
    } catch (const InputError& e) {
        return e.what();
    }
    return {};
}

/// The text with line `number` (1-based) replaced by `line`.
std::string withLine(const std::string& text, size_t number, const std::string& line) {
    std::istringstream in(text);
    std::string out, l;
    for (size_t k = 1; std::getline(in, l); ++k) out += (k == number ? line : l) + "\n";
    return out;
}

std::string lineOf(const std::string& text, size_t number);

std::string firstLines(const std::string& text, size_t count) {
    std::istringstream in(text);
    std::string out, l;
    for (size_t k = 0; k < count && std::getline(in, l); ++k) out += l + "\n";
    return out;
}

/// The text with field `index` (0-based) of line `number` replaced by `value`.
std::string withField(const std::string& text, size_t number, size_t index, const std::string& value) {
    std::vector<std::string> f;
    std::stringstream s(lineOf(text, number));
    for (std::string x; std::getline(s, x, ',');) f.push_back(x);
    f.at(index) = value;
    std::string line;
    for (size_t k = 0; k < f.size(); ++k) line += (k ? "," : "") + f[k];
    return withLine(text, number, line);
}

std::string lineOf(const std::string& text, size_t number) {
    std::istringstream in(text);
    std::string l;
    for (size_t k = 1; std::getline(in, l); ++k)
        if (k == number) return l;
    return {};
}

}  // namespace

TEST_CASE("weather file: a year of Chicago O'Hare (TMY3)", "[daylight][annual]") {
    const auto w = scene::readWeatherFile(test::sourcePath(kChicago));
    CHECK(w.city == "Chicago Ohare Intl Ap");
    CHECK(w.latitudeDeg == 41.98);
    CHECK(w.longitudeDeg == -87.92);
    CHECK(w.timeZoneHours == -6);
    REQUIRE(w.hours.size() == 8760);
    // 15 March, the hour ending at 12:00 (line 8 + 73 · 24 + 12 of the file).
    const auto& h = w.hours[73 * 24 + 11];
    CHECK(h.month == 3);
    CHECK(h.day == 15);
    CHECK(h.hour == 12);
    CHECK(h.directNormalIrradiance == 942);
    CHECK(h.diffuseHorizontalIrradiance == 89);
    CHECK(h.dewPointC == -4.4);
    CHECK(w.hours.back().month == 12);
    CHECK(w.hours.back().hour == 24);
}

TEST_CASE("weather file: truncated, corrupted and foreign files are refused with their place", "[daylight][annual]") {
    const std::string text = chicagoText();
    // Cut short: the last day gone.
    CHECK(refused(firstLines(text, 8 + 8736)).find("8736 hours") != std::string::npos);
    // Cut in the middle of a line (8 header lines, then the hours).
    const std::string cut = firstLines(text, 8767);
    CHECK(refused(cut.substr(0, cut.size() - 40)).find("w.epw: line 8767: an hour has 35 fields") != std::string::npos);
    // A field that is not a number; a missing direct radiation (9999); an hour out of order.
    CHECK(refused(withField(text, 100, 14, "x")).find("w.epw: line 100: field 15 (direct normal radiation): expected a "
                                                     "number") != std::string::npos);
    CHECK(refused(withField(text, 2000, 14, "9999")).find("line 2000: field 15 (direct normal radiation) is missing") !=
          std::string::npos);
    CHECK(refused(withField(text, 2000, 15, "-3")).find("line 2000: field 16") != std::string::npos);
    CHECK(refused(withLine(text, 3000, lineOf(text, 2999))).find("line 3000") != std::string::npos);
    CHECK(refused("This is not a weather file\n").find("not an EnergyPlus weather file") != std::string::npos);
    CHECK(refused(withLine(text, 1, "LOCATION,Nowhere,,,,0,95.0,10,0,0")).find("latitude 95") != std::string::npos);
    CHECK_THROWS_AS(scene::readWeatherFile("/nonexistent/x.epw"), InputError);
}
