#include <tonemap/white_balance.h>

#include <core/colour_space.h>
#include <core/input_error.h>
#include <core/colour_temperature.h>

#include <fmt/format.h>

#include <cmath>

namespace rayrad::tonemap {

namespace {

/// XYZ → Bradford cone responses ρσβ (Lam 1985).
constexpr Matrix3 kBradford{{{0.8951, 0.2664, -0.1614}, {-0.7502, 1.7135, 0.0367}, {0.0389, -0.0685, 1.0296}}};

Matrix3 multiply(const Matrix3& a, const Matrix3& b) {
    Matrix3 m{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k) m[i][j] += a[i][k] * b[k][j];
    return m;
}

Matrix3 inverse(const Matrix3& m) {
    const double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                       m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    Matrix3 r{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            const int a = (j + 1) % 3, b = (j + 2) % 3, c = (i + 1) % 3, d = (i + 2) % 3;
            r[i][j] = (m[a][c] * m[b][d] - m[a][d] * m[b][c]) / det;  // cofactor, transposed
        }
    return r;
}

Rgb meanOver(const HdrImage& image, int x0, int y0, int w, int h) {
    Rgb sum(0.0);
    for (int y = y0; y < y0 + h; ++y)
        for (int x = x0; x < x0 + w; ++x)
            if (std::isfinite(luminance(image.at(x, y)))) sum += image.at(x, y);
    return sum;
}

}  // namespace

Rgb applyMatrix(const Matrix3& m, const Rgb& c) {
    return Rgb(m[0][0] * c.r + m[0][1] * c.g + m[0][2] * c.b, m[1][0] * c.r + m[1][1] * c.g + m[1][2] * c.b,
               m[2][0] * c.r + m[2][1] * c.g + m[2][2] * c.b);
}

WhiteBalance parseWhiteBalance(const std::string& text) {
    auto bad = [&](const std::string& why) {
        return InputError(placeMessage("", "--white-balance", why + ", got \"" + text + "\""));
    };
    WhiteBalance wb;
    if (text == "none") return wb;
    if (text == "grey-world" || text == "gray-world") {
        wb.kind = WhiteBalance::Kind::GreyWorld;
        return wb;
    }
    if (text.rfind("region:", 0) == 0) {
        int v[4];
        char end = 0;
        if (std::sscanf(text.c_str() + 7, "%d,%d,%d,%d%c", &v[0], &v[1], &v[2], &v[3], &end) != 4 || v[0] < 0 || v[1] < 0 ||
            v[2] <= 0 || v[3] <= 0)
            throw bad("expected region:x,y,width,height in pixels (width and height positive)");
        wb.kind = WhiteBalance::Kind::Region;
        wb.region = {v[0], v[1], v[2], v[3]};
        return wb;
    }
    std::string number = text;
    if (!number.empty() && (number.back() == 'K' || number.back() == 'k')) number.pop_back();
    double k = 0;
    size_t used = 0;
    try {
        k = std::stod(number, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used == 0 || used != number.size())
        throw bad("expected none, a colour temperature such as 3000K, grey-world or region:x,y,width,height");
    if (!(k >= kMinColourTemperature && k <= kMaxColourTemperature))
        throw bad(fmt::format("expected a colour temperature from {:g} to {:g} K", kMinColourTemperature,
                              kMaxColourTemperature));
    wb.kind = WhiteBalance::Kind::Temperature;
    wb.kelvin = k;
    return wb;
}

void checkWhiteBalance(const WhiteBalance& wb, int width, int height) {
    if (wb.kind != WhiteBalance::Kind::Region) return;
    const auto& r = wb.region;
    if (r[0] + r[2] > width || r[1] + r[3] > height)
        throw InputError(placeMessage("", "--white-balance",
                                      fmt::format("the region {},{} {}×{} is not inside the {}×{} image", r[0], r[1], r[2],
                                                  r[3], width, height)));
}

Rgb sourceWhite(const HdrImage& image, const WhiteBalance& wb) {
    Rgb white(1.0);
    switch (wb.kind) {
    case WhiteBalance::Kind::None: return white;
    case WhiteBalance::Kind::Temperature: white = colourOfTemperature(wb.kelvin); break;
    case WhiteBalance::Kind::GreyWorld: white = meanOver(image, 0, 0, image.width, image.height); break;
    case WhiteBalance::Kind::Region: {
        checkWhiteBalance(wb, image.width, image.height);
        const auto& r = wb.region;
        white = meanOver(image, r[0], r[1], r[2], r[3]);
        break;
    }
    }
    const double y = luminance(white);
    if (!(y > 0) || white.r <= 0 || white.g <= 0 || white.b <= 0)
        throw InputError(placeMessage("", "--white-balance", "the white to balance from has no light in some channel (a black region?)"));
    return white / y;
}

Matrix3 whiteBalanceMatrix(const HdrImage& image, const WhiteBalance& wb) {
    Matrix3 identity{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
    if (wb.kind == WhiteBalance::Kind::None) return identity;
    const Rgb white = sourceWhite(image, wb);
    Matrix3 rgbToXyz{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) rgbToXyz[i][j] = kRec709ToXyz[i][j];
    const Matrix3 toCones = multiply(kBradford, rgbToXyz);  // RGB → ρσβ
    const Rgb src = applyMatrix(toCones, white), dst = applyMatrix(toCones, Rgb(1.0));  // D65 = (1, 1, 1), Y = 1
    Matrix3 scale{};
    for (int i = 0; i < 3; ++i) scale[i][i] = dst[i] / src[i];
    return multiply(inverse(toCones), multiply(scale, toCones));
}

std::string describe(const WhiteBalance& wb, const HdrImage& image) {
    switch (wb.kind) {
    case WhiteBalance::Kind::None: return "none";
    case WhiteBalance::Kind::Temperature: return fmt::format("{:g} K → D65 (Bradford)", wb.kelvin);
    case WhiteBalance::Kind::GreyWorld:
    case WhiteBalance::Kind::Region: {
        const Rgb w = sourceWhite(image, wb);
        const std::string what = wb.kind == WhiteBalance::Kind::GreyWorld
                                     ? std::string("grey world")
                                     : fmt::format("region {},{} {}×{}", wb.region[0], wb.region[1], wb.region[2], wb.region[3]);
        return fmt::format("{} (white {:.3f}, {:.3f}, {:.3f}) → D65 (Bradford)", what, w.r, w.g, w.b);
    }
    }
    return "";
}

}  // namespace rayrad::tonemap
