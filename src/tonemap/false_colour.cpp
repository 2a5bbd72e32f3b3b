#include <tonemap/false_colour.h>

#include <core/input_error.h>

#include <tonemap/text_drawing.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace rayrad::tonemap {

namespace {

constexpr int kFontSize = 15;        ///< px
constexpr int kLegendWidth = 170;    ///< px, to the right of the field
constexpr int kMargin = 12;          ///< px

/// Samples of Google's Turbo colour map at t = 0, 1/8, …, 1 (sRGB-encoded).
constexpr float kTurbo[9][3] = {{0.190f, 0.072f, 0.232f}, {0.274f, 0.409f, 0.895f}, {0.157f, 0.702f, 0.941f},
                                {0.102f, 0.894f, 0.651f}, {0.471f, 0.992f, 0.329f}, {0.839f, 0.886f, 0.204f},
                                {0.992f, 0.647f, 0.192f}, {0.890f, 0.267f, 0.043f}, {0.480f, 0.016f, 0.010f}};

/// Position of value v on the scale, in [0, 1].
double scalePosition(double v, double lo, double hi, bool log) {
    if (!(v > lo)) return 0;
    if (v >= hi) return 1;
    return log ? std::log(v / lo) / std::log(hi / lo) : (v - lo) / (hi - lo);
}

std::string label(double v) {
    if (v == 0) return "0";
    const double a = std::abs(v);
    if (a >= 1e5 || a < 1e-2) return fmt::format("{:.2g}", v);
    return fmt::format("{:g}", std::round(v * 100) / 100);
}

}  // namespace

std::vector<double> scaleLevels(double minimum, double maximum, const FalseColourOptions& o) {
    std::vector<double> levels;
    if (o.logScale) {
        const double lo = maximum / std::pow(10.0, o.decades);
        for (double e = std::floor(std::log10(lo)); e <= std::ceil(std::log10(maximum)); e += 1)
            for (double m : {1.0, 2.0, 5.0}) {
                const double v = m * std::pow(10.0, e);
                if (v >= lo * (1 - 1e-9) && v <= maximum * (1 + 1e-9)) levels.push_back(v);
            }
        return levels;
    }
    // From 0, unless the field is uniform enough that 0 would waste the scale: then from
    // a level below its minimum, so the isolines fall where the values are.
    const double from = minimum > 0.25 * maximum ? minimum : 0.0;
    double step = 0;
    for (double e = std::floor(std::log10(maximum - from)) - 1; step == 0; e += 1)
        for (double m : {1.0, 2.0, 2.5, 5.0}) {
            const double s = m * std::pow(10.0, e);
            if ((maximum - from) / s <= 8) {
                step = s;
                break;
            }
        }
    for (double v = std::floor(from / step) * step; v <= maximum + step * (1 - 1e-9); v += step) levels.push_back(v);
    return levels;
}

void paletteColour(double t, float rgb[3]) {
    const double x = std::clamp(t, 0.0, 1.0) * 8;
    const int i = std::min(7, static_cast<int>(x));
    const double f = x - i;
    for (int c = 0; c < 3; ++c) {
        const double encoded = kTurbo[i][c] + f * (kTurbo[i + 1][c] - kTurbo[i][c]);
        rgb[c] = static_cast<float>(encoded);  // drawn as display values (sRGB-encoded)
    }
}

Picture renderFalseColour(const ScalarField& field, const FalseColourOptions& o) {
    double top = 0, bottom = std::numeric_limits<double>::infinity();
    for (double v : field.values)
        if (std::isfinite(v)) top = std::max(top, v), bottom = std::min(bottom, v);
    const double peak = o.maximum > 0 ? o.maximum : (top > 0 ? top : 1.0);
    const std::vector<double> levels = scaleLevels(std::isfinite(bottom) ? bottom : 0.0, peak, o);
    // The scale runs from the lowest level to the highest (log: three decades below the peak).
    const double maximum = o.logScale ? peak : levels.back();
    const double lo = o.logScale ? peak / std::pow(10.0, o.decades) : levels.front();

    // The field, each value an n × n block, bilinear between the values' centres.
    const int n = std::max(1, o.pixelsPerValue);
    const int fw = field.width * n, fh = field.height * n;
    // The title's lines above the field (the picture widened to hold the longest, at about
    // 0.56 font sizes a character).
    std::vector<std::string> titleLines;
    for (size_t start = 0; start <= o.title.size();) {
        const size_t end = std::min(o.title.find('\n', start), o.title.size());
        titleLines.push_back(o.title.substr(start, end - start));
        start = end + 1;
    }
    size_t longest = 0;
    for (const auto& line : titleLines) longest = std::max(longest, line.size());
    const int fieldTop = kFontSize * (static_cast<int>(titleLines.size()) + 1);  // below the margin
    const int width = std::max(fw + kLegendWidth + 2 * kMargin,
                               static_cast<int>(0.56 * kFontSize * static_cast<double>(longest)) + 2 * kMargin);
    const int height = std::max(fh, 260) + 2 * kMargin + fieldTop;
    Picture out;
    out.width = width;
    out.height = height;
    out.rgb.assign(static_cast<size_t>(width) * height * 3, 255);
    auto set = [&](int x, int y, const float rgb[3]) {
        if (x < 0 || y < 0 || x >= width || y >= height) return;
        for (int c = 0; c < 3; ++c)
            out.rgb[(static_cast<size_t>(y) * width + x) * 3 + c] = static_cast<uint8_t>(std::lround(std::clamp(rgb[c], 0.0f, 1.0f) * 255));
    };
    auto at = [&](int x, int y) { return field.values[static_cast<size_t>(y) * field.width + x]; };
    std::vector<double> value(static_cast<size_t>(fw) * fh, std::numeric_limits<double>::quiet_NaN());
    for (int py = 0; py < fh; ++py)
        for (int px = 0; px < fw; ++px) {
            const double fx = (px + 0.5) / n - 0.5, fy = (py + 0.5) / n - 0.5;
            const int x0 = std::clamp(static_cast<int>(std::floor(fx)), 0, field.width - 1);
            const int y0 = std::clamp(static_cast<int>(std::floor(fy)), 0, field.height - 1);
            const int x1 = std::min(x0 + 1, field.width - 1), y1 = std::min(y0 + 1, field.height - 1);
            const double tx = std::clamp(fx - x0, 0.0, 1.0), ty = std::clamp(fy - y0, 0.0, 1.0);
            const double own = at(std::clamp(px / n, 0, field.width - 1), std::clamp(py / n, 0, field.height - 1));
            if (!std::isfinite(own)) continue;  // no value here (outside a work plane's outline)
            double sum = 0, weight = 0;
            const double corner[4] = {at(x0, y0), at(x1, y0), at(x0, y1), at(x1, y1)};
            const double w[4] = {(1 - tx) * (1 - ty), tx * (1 - ty), (1 - tx) * ty, tx * ty};
            for (int k = 0; k < 4; ++k)
                if (std::isfinite(corner[k])) sum += w[k] * corner[k], weight += w[k];
            value[static_cast<size_t>(py) * fw + px] = weight > 0 ? sum / weight : own;
        }
    auto levelIndex = [&](double v) {
        return static_cast<int>(std::upper_bound(levels.begin(), levels.end(), v) - levels.begin());
    };
    for (int py = 0; py < fh; ++py)
        for (int px = 0; px < fw; ++px) {
            const double v = value[static_cast<size_t>(py) * fw + px];
            float rgb[3] = {0.85f, 0.85f, 0.85f};  // grey where there is no value
            if (std::isfinite(v)) {
                paletteColour(scalePosition(v, lo, maximum, o.logScale), rgb);
                if (o.isolines) {
                    // An isoline where this pixel and its right or lower neighbour lie on
                    // different sides of a level.
                    const int here = levelIndex(v);
                    const double right = px + 1 < fw ? value[static_cast<size_t>(py) * fw + px + 1] : v;
                    const double below = py + 1 < fh ? value[static_cast<size_t>(py + 1) * fw + px] : v;
                    if ((std::isfinite(right) && levelIndex(right) != here) || (std::isfinite(below) && levelIndex(below) != here))
                        rgb[0] = rgb[1] = rgb[2] = 0.08f;
                }
            }
            set(kMargin + px, kMargin + fieldTop + py, rgb);
        }

    // The legend: a colour bar with a tick and a number at every level, the title above.
    const int barX = kMargin + fw + 20, barTop = kMargin + fieldTop, barHeight = std::max(fh, 260) - kFontSize;
    for (int y = 0; y < barHeight; ++y) {
        float rgb[3];
        paletteColour(1.0 - static_cast<double>(y) / (barHeight - 1), rgb);
        for (int x = 0; x < 24; ++x) set(barX + x, barTop + y, rgb);
    }
    const float ink[3] = {0.05f, 0.05f, 0.05f};
    std::vector<TextLabel> labels;
    for (double v : levels) {
        const int y = barTop + static_cast<int>(std::lround((1 - scalePosition(v, lo, maximum, o.logScale)) * (barHeight - 1)));
        for (int x = 24; x < 30; ++x) set(barX + x, y, ink);
        labels.push_back({barX + 34, y, label(v) + " " + o.unit, TextLabel::Align::Left, true, kFontSize});
    }
    for (size_t k = 0; k < titleLines.size(); ++k)
        labels.push_back({kMargin, kMargin + kFontSize * static_cast<int>(k + 1), titleLines[k], TextLabel::Align::Left,
                          false, kFontSize});
    drawText(out.rgb, width, height, labels);
    return out;
}

Picture stackPictures(const std::vector<Picture>& pictures) {
    Picture out;
    for (const auto& p : pictures) out.width = std::max(out.width, p.width), out.height += p.height;
    out.rgb.assign(static_cast<size_t>(out.width) * out.height * 3, 255);
    int y0 = 0;
    for (const auto& p : pictures) {
        for (int y = 0; y < p.height; ++y)
            std::copy_n(&p.rgb[static_cast<size_t>(y) * p.width * 3], static_cast<size_t>(p.width) * 3,
                        &out.rgb[(static_cast<size_t>(y0 + y) * out.width) * 3]);
        y0 += p.height;
    }
    return out;
}

}  // namespace rayrad::tonemap
