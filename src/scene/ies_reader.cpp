// IES LM-63 photometric files: 1986 (no version line, free-text header), 1991, 1995,
// 2002 and 2019. Everything after the TILT= line is one stream of numbers separated by
// white space or commas, wrapped at any count; each number remembers its line for
// messages.
#include <scene/photometry.h>

#include <core/input_error.h>
#include <core/input_file.h>
#include <scene/text_lines.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>

namespace rayrad::scene {

namespace {

constexpr double kFeet = 0.3048;  // m
constexpr size_t kMaxAngles = 10000;

struct Number {
    double value = 0;
    int line = 0;
    std::string text;
};

std::string trim(const std::string& s) {
    size_t a = s.find_first_not_of(" \t"), b = s.find_last_not_of(" \t");
    return a == std::string::npos ? "" : s.substr(a, b - a + 1);
}

/// Reads numbers one by one, naming the line of each in errors.
class NumberStream {
  public:
    NumberStream(const std::vector<std::string>& lines, size_t first, std::string name)
        : m_name(std::move(name)), m_lastLine(static_cast<int>(lines.size())) {
        for (size_t l = first; l < lines.size(); ++l) {
            std::string line = lines[l];
            std::replace(line.begin(), line.end(), ',', ' ');
            std::istringstream words(line);
            for (std::string w; words >> w;) m_numbers.push_back({0.0, static_cast<int>(l) + 1, w});
        }
    }

    [[noreturn]] void fail(int line, const std::string& why) const {
        throw InputError(placeMessage(m_name, fmt::format("line {}", line), why));
    }

    /// The next number, described by `what` in a message if it is missing or not a number.
    double next(const std::string& what) {
        if (m_next >= m_numbers.size()) fail(m_lastLine, "the file ends before " + what);
        Number& n = m_numbers[m_next++];
        try {
            size_t used = 0;
            n.value = std::stod(n.text, &used);
            if (used != n.text.size()) throw std::invalid_argument(n.text);
        } catch (const std::exception&) {
            fail(n.line, fmt::format("expected {}, got '{}'", what, n.text));
        }
        if (!std::isfinite(n.value)) fail(n.line, fmt::format("{} is not finite: '{}'", what, n.text));
        return n.value;
    }
    int line() const { return m_numbers[m_next > 0 ? m_next - 1 : 0].line; }

    /// A whole number in [lo, hi].
    size_t count(const std::string& what, double lo, double hi) {
        const double v = next(what);
        if (v != std::floor(v) || v < lo || v > hi)
            fail(line(), fmt::format("expected {} (a whole number from {:g} to {:g}), got {:g}", what, lo, hi, v));
        return static_cast<size_t>(v);
    }

    /// `n` angles, ascending.
    std::vector<double> angles(size_t n, const std::string& what, double lo, double hi) {
        std::vector<double> out;
        for (size_t i = 0; i < n; ++i) {
            const double a = next(fmt::format("{} angle {} of {}", what, i + 1, n));
            if (a < lo - 1e-9 || a > hi + 1e-9)
                fail(line(), fmt::format("{} angle {:g} is outside {:g} to {:g} degrees", what, a, lo, hi));
            if (!out.empty() && a <= out.back())
                fail(line(), fmt::format("{} angles must increase: {:g} after {:g}", what, a, out.back()));
            out.push_back(a);
        }
        return out;
    }

    size_t remaining() const { return m_numbers.size() - m_next; }
    /// The next number's place and text, not read (remaining() > 0).
    const Number& peek() const { return m_numbers[m_next]; }

  private:
    std::string m_name;
    int m_lastLine;
    std::vector<Number> m_numbers;
    size_t m_next = 0;
};

/// The tilt block: lamp-to-luminaire geometry, the number of angles, angles, factors.
void readTilt(NumberStream& in, Photometry& p) {
    in.count("the TILT lamp-to-luminaire geometry (1, 2 or 3)", 1, 3);
    const size_t n = in.count("the number of TILT angles", 1, kMaxAngles);
    p.tiltAngles = in.angles(n, "TILT", -180, 180);
    for (size_t i = 0; i < n; ++i) {
        const double f = in.next(fmt::format("TILT factor {} of {}", i + 1, n));
        if (f < 0) in.fail(in.line(), fmt::format("TILT factor {:g} is negative", f));
        p.tiltFactors.push_back(f);
    }
}

}  // namespace

Photometry parseIes(const std::string& text, const std::string& name) {
    const std::vector<std::string> lines = splitLines(text);
    Photometry p;
    p.file = name;
    const std::string first = lines.empty() ? "" : trim(lines[0]);
    const bool is2019 = first.rfind("IES:LM-63-2019", 0) == 0;
    if (first.rfind("IESNA", 0) == 0 || first.rfind("IES:", 0) == 0) p.format = "IES " + first;
    else p.format = "IES LM-63-1986 (no version line)";
    // The header ends at TILT=; keyword lines before it are not needed for the light.
    size_t tiltLine = lines.size();
    for (size_t l = 0; l < lines.size(); ++l)
        if (trim(lines[l]).rfind("TILT", 0) == 0 && trim(lines[l]).find('=') != std::string::npos) {
            tiltLine = l;
            break;
        }
    if (tiltLine == lines.size())
        throw InputError(placeMessage(name, "", "no TILT= line: not an IES LM-63 photometric file"));
    const std::string tiltLineText = trim(lines[tiltLine]);
    const std::string tilt = trim(tiltLineText.substr(tiltLineText.find('=') + 1));
    NumberStream in(lines, tiltLine + 1, name);
    if (tilt == "INCLUDE") {
        readTilt(in, p);
    } else if (tilt != "NONE") {
        // A tilt file beside the photometric file.
        const std::string path = (std::filesystem::path(name).parent_path() / tilt).string();
        const std::string tiltText = readInputFile(path, "IES tilt file", size_t(1) << 20);
        NumberStream tiltIn(splitLines(tiltText), 0, path);
        readTilt(tiltIn, p);
    }

    const double lamps = static_cast<double>(in.count("the number of lamps", 1, 1000));
    const double lumens = in.next("the lumens per lamp");
    if (!(lumens > 0 || lumens == -1))
        in.fail(in.line(), fmt::format("lumens per lamp must be positive, or -1 for absolute photometry; got {:g}", lumens));
    const double multiplier = in.next("the candela multiplier");
    if (!(multiplier > 0)) in.fail(in.line(), fmt::format("the candela multiplier must be positive, got {:g}", multiplier));
    const size_t nv = in.count("the number of vertical angles", 1, kMaxAngles);
    const size_t nh = in.count("the number of horizontal angles", 1, kMaxAngles);
    const size_t type = in.count("the photometric type (1 C, 2 B, 3 A)", 1, 3);
    p.type = type == 1 ? PhotometricType::C : type == 2 ? PhotometricType::B : PhotometricType::A;
    const double unit = in.count("the units type (1 feet, 2 metres)", 1, 2) == 1 ? kFeet : 1.0;
    const double width = in.next("the luminous opening's width") * unit;
    const double length = in.next("the luminous opening's length") * unit;
    const double height = in.next("the luminous opening's height") * unit;
    const double ballast = in.next("the ballast factor");
    if (!(ballast > 0)) in.fail(in.line(), fmt::format("the ballast factor must be positive, got {:g}", ballast));
    // Before LM-63-2019 this field was the ballast-lamp photometric factor (a multiplier,
    // 1 in 2002's "future use"); 2019 made it the file generation type, not a factor.
    const double thirdFactor = in.next(is2019 ? "the file generation type" : "the ballast-lamp photometric factor");
    const double factor = multiplier * ballast * (is2019 || !(thirdFactor > 0) ? 1.0 : thirdFactor);
    p.inputWatts = in.next("the input watts");

    const bool typeC = p.type == PhotometricType::C;
    p.vertical = in.angles(nv, "vertical", typeC ? 0 : -90, typeC ? 180 : 90);
    p.horizontal = in.angles(nh, "horizontal", typeC ? 0 : -180, typeC ? 360 : 180);
    p.candela.assign(nh, std::vector<double>(nv));
    for (size_t h = 0; h < nh; ++h)
        for (size_t v = 0; v < nv; ++v) {
            const double cd = in.next(fmt::format("candela value {} of {} (horizontal angle {:g}, vertical {:g})",
                                                  h * nv + v + 1, nh * nv, p.horizontal[h], p.vertical[v]));
            if (cd < 0) in.fail(in.line(), fmt::format("candela value {:g} is negative", cd));
            p.candela[h][v] = cd * factor;
        }

    // Numbers left over mean the counts and the data disagree (one horizontal angle
    // counted, two listed): every value after the miscount would be shifted.
    if (in.remaining() > 0) {
        const Number& extra = in.peek();
        in.fail(extra.line, fmt::format("{} number(s) after the {} × {} candela values (the first '{}'): the counts of "
                                        "vertical and horizontal angles do not match the data",
                                        in.remaining(), nv, nh, extra.text));
    }
    p.absolute = lumens == -1;
    p.lampFlux = p.absolute ? 0 : lamps * lumens;
    p.round = width < 0 || length < 0;
    p.width = std::abs(width);
    p.length = p.round ? 0 : std::abs(length);
    p.height = std::abs(height);
    return p;
}

}  // namespace rayrad::scene
