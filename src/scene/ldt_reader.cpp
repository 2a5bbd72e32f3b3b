// EULUMDAT (.ldt) photometric files: one value per line at fixed line numbers (blank
// lines count), decimal commas allowed, intensities in cd per 1000 lm of lamp flux.
#include <scene/photometry.h>

#include <core/input_error.h>
#include <scene/text_lines.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace rayrad::scene {

namespace {

class LdtLines {
  public:
    LdtLines(const std::string& text, std::string name) : m_name(std::move(name)), m_lines(splitLines(text)) {}

    [[noreturn]] void fail(size_t line, const std::string& why) const {
        throw InputError(placeMessage(m_name, fmt::format("line {}", line), why));
    }

    /// Line n (1-based), trimmed.
    std::string text(size_t n, const std::string& what) const {
        if (m_lines.empty()) throw InputError(placeMessage(m_name, "", "the file is empty"));
        if (n > m_lines.size())
            fail(m_lines.size(), "the file ends before line " + std::to_string(n) + " (" + what + ")");
        const std::string& s = m_lines[n - 1];
        const size_t a = s.find_first_not_of(" \t"), b = s.find_last_not_of(" \t");
        return a == std::string::npos ? "" : s.substr(a, b - a + 1);
    }

    /// The number on line n (a decimal comma is a decimal point); an empty line is 0.
    double number(size_t n, const std::string& what) const {
        std::string s = text(n, what);
        if (s.empty()) return 0;
        std::replace(s.begin(), s.end(), ',', '.');
        double v = 0;
        try {
            size_t used = 0;
            v = std::stod(s, &used);
            if (used != s.size()) throw std::invalid_argument(s);
        } catch (const std::exception&) {
            fail(n, fmt::format("expected {}, got '{}'", what, s));
        }
        if (!std::isfinite(v)) fail(n, fmt::format("{} is not finite: '{}'", what, s));
        return v;
    }

    size_t count(size_t n, const std::string& what, double lo, double hi) const {
        const double v = number(n, what);
        if (v != std::floor(v) || v < lo || v > hi)
            fail(n, fmt::format("expected {} (a whole number from {:g} to {:g}), got {:g}", what, lo, hi, v));
        return static_cast<size_t>(v);
    }

  private:
    std::string m_name;
    std::vector<std::string> m_lines;
};

}  // namespace

Photometry parseLdt(const std::string& text, const std::string& name) {
    const LdtLines in(text, name);
    Photometry p;
    p.file = name;
    p.format = "EULUMDAT";
    p.type = PhotometricType::C;
    in.count(2, "the type indicator Ityp (0–3)", 0, 3);
    const size_t isym = in.count(3, "the symmetry indicator Isym (0–4)", 0, 4);
    const size_t mc = in.count(4, "the number of C planes Mc", 1, 3600);
    const size_t ng = in.count(6, "the number of intensities per plane Ng", 1, 3600);
    if ((isym == 2 || isym == 3) && mc % 2)
        in.fail(4, fmt::format("Isym {} needs an even number of C planes, got {}", isym, mc));
    if (isym == 4 && mc % 4) in.fail(4, fmt::format("Isym 4 needs a multiple of 4 C planes, got {}", mc));
    const double mm = 0.001;
    const double openingLength = in.number(16, "the luminous area's length or diameter (mm)") * mm;
    const double openingWidth = in.number(17, "the luminous area's width (mm; 0: round)") * mm;
    p.round = openingWidth == 0;
    // EULUMDAT's luminous length runs across the C0 plane, along C90–C270 (the lamp axis of
    // a linear luminaire; DIALux's and Relux's UGR tables of files with luminous sides agree
    // with it, not with the length along C0); Photometry's `length` is along C0.
    p.width = std::abs(openingLength);
    p.length = p.round ? 0 : std::abs(openingWidth);
    p.height = std::abs(in.number(18, "the luminous area's height at C0 (mm)")) * mm;
    const double lorl = in.number(23, "the light output ratio LORL (%)");
    if (lorl < 0 || lorl > 1000)
        in.fail(23, fmt::format("the light output ratio LORL {:g} % is not a percentage", lorl));
    p.statedLor = lorl / 100;
    const double conversion = in.number(24, "the conversion factor for intensities");
    if (!(conversion > 0)) in.fail(24, fmt::format("the conversion factor must be positive, got {:g}", conversion));
    const size_t sets = in.count(26, "the number of lamp sets", 1, 20);
    // Set by set, six lines each (EN 13032-4; as DIALux and the manufacturers' tools write
    // them): number of lamps, lamp type, total lamp flux (lm), colour, colour rendering,
    // wattage with ballast. The first set is the standard one, the intensities' reference.
    constexpr size_t kSetLines = 6;
    const size_t lampsLine = 27, typeLine = 28, fluxLine = 29, wattsLine = 32;
    p.lampSets = static_cast<int>(sets);
    p.lampCount = in.number(lampsLine, "the number of lamps of set 1");  // negative: absolute photometry in some files
    p.lampType = in.text(typeLine, "the lamp type of set 1");
    const double flux = in.number(fluxLine, "the total lamp flux of set 1 (lm)");
    if (!(flux > 0)) in.fail(fluxLine, fmt::format("the lamp flux of set 1 must be positive, got {:g}", flux));
    p.inputWatts = in.number(wattsLine, "the wattage of set 1 (W)");
    for (size_t s = 1; s < sets; ++s)  // the other sets are read, so a short block is an error
        in.number(fluxLine + s * kSetLines, fmt::format("the total lamp flux of set {} (lm)", s + 1));
    p.lampFlux = flux;
    const size_t anglesLine = 27 + kSetLines * sets + 10;  // after the ten direct ratios
    std::vector<double> c(mc), g(ng);
    for (size_t i = 0; i < mc; ++i) c[i] = in.number(anglesLine + i, fmt::format("C angle {} of {}", i + 1, mc));
    for (size_t i = 0; i < ng; ++i) g[i] = in.number(anglesLine + mc + i, fmt::format("γ angle {} of {}", i + 1, ng));
    for (size_t i = 1; i < mc; ++i)
        if (c[i] <= c[i - 1])
            in.fail(anglesLine + i, fmt::format("C angles must increase: {:g} after {:g}", c[i], c[i - 1]));
    for (size_t i = 1; i < ng; ++i)
        if (g[i] <= g[i - 1])
            in.fail(anglesLine + mc + i, fmt::format("γ angles must increase: {:g} after {:g}", g[i], g[i - 1]));
    if (c.front() < 0 || c.back() >= 360) in.fail(anglesLine, "C angles must lie in [0, 360)");
    if (g.front() < 0 || g.back() > 180) in.fail(anglesLine + mc, "γ angles must lie in [0, 180]");
    // The stored planes (EN 13032-1): all, one, C0–C180, C90–C270 or C0–C90.
    size_t firstPlane = 0, planes = mc;
    if (isym == 1) planes = 1;
    if (isym == 2) planes = mc / 2 + 1;
    if (isym == 3) firstPlane = mc / 4, planes = mc / 2 + 1;
    if (isym == 4) planes = mc / 4 + 1;
    p.vertical = g;
    const double scale = flux / 1000 * conversion;  // cd/klm → cd
    size_t line = anglesLine + mc + ng;
    for (size_t k = 0; k < planes; ++k) {
        p.horizontal.push_back(isym == 1 ? 0.0 : c[firstPlane + k]);
        std::vector<double> plane(ng);
        for (size_t i = 0; i < ng; ++i, ++line) {
            const double v = in.number(line, fmt::format("intensity {} of C plane {:g}", i + 1, p.horizontal.back()));
            if (v < 0) in.fail(line, fmt::format("intensity {:g} cd/klm is negative", v));
            plane[i] = v * scale;
        }
        p.candela.push_back(std::move(plane));
    }
    return p;
}

}  // namespace rayrad::scene
