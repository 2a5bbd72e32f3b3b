#include <app/plot.h>

#include <tonemap/image_io.h>

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <map>

namespace rayrad::app {

namespace {

/// 5×7 glyphs, one byte per row, bit 4 = leftmost column.
const std::map<char, std::array<uint8_t, 7>>& font() {
    static const std::map<char, std::array<uint8_t, 7>> f = {
        {'0', {14, 17, 19, 21, 25, 17, 14}}, {'1', {4, 12, 4, 4, 4, 4, 14}},     {'2', {14, 17, 1, 2, 4, 8, 31}},
        {'3', {31, 2, 4, 2, 1, 17, 14}},     {'4', {2, 6, 10, 18, 31, 2, 2}},    {'5', {31, 16, 30, 1, 1, 17, 14}},
        {'6', {6, 8, 16, 30, 17, 17, 14}},   {'7', {31, 1, 2, 4, 8, 8, 8}},      {'8', {14, 17, 17, 14, 17, 17, 14}},
        {'9', {14, 17, 17, 15, 1, 2, 12}},   {'.', {0, 0, 0, 0, 0, 12, 12}},     {'-', {0, 0, 0, 31, 0, 0, 0}},
        {'+', {0, 4, 4, 31, 4, 4, 0}},       {'%', {24, 25, 2, 4, 8, 19, 3}},    {'(', {2, 4, 8, 8, 8, 4, 2}},
        {')', {8, 4, 2, 2, 2, 4, 8}},        {',', {0, 0, 0, 0, 12, 4, 8}},      {':', {0, 12, 12, 0, 12, 12, 0}},
        {'/', {1, 1, 2, 4, 8, 16, 16}},      {'=', {0, 0, 31, 0, 31, 0, 0}},     {'A', {14, 17, 17, 31, 17, 17, 17}},
        {'B', {30, 17, 17, 30, 17, 17, 30}}, {'C', {14, 17, 16, 16, 16, 17, 14}}, {'D', {28, 18, 17, 17, 17, 18, 28}},
        {'E', {31, 16, 16, 30, 16, 16, 31}}, {'F', {31, 16, 16, 30, 16, 16, 16}}, {'G', {14, 17, 16, 23, 17, 17, 15}},
        {'H', {17, 17, 17, 31, 17, 17, 17}}, {'I', {14, 4, 4, 4, 4, 4, 14}},     {'J', {7, 2, 2, 2, 2, 18, 12}},
        {'K', {17, 18, 20, 24, 20, 18, 17}}, {'L', {16, 16, 16, 16, 16, 16, 31}}, {'M', {17, 27, 21, 21, 17, 17, 17}},
        {'N', {17, 17, 25, 21, 19, 17, 17}}, {'O', {14, 17, 17, 17, 17, 17, 14}}, {'P', {30, 17, 17, 30, 16, 16, 16}},
        {'Q', {14, 17, 17, 17, 21, 18, 13}}, {'R', {30, 17, 17, 30, 20, 18, 17}}, {'S', {15, 16, 16, 14, 1, 1, 30}},
        {'T', {31, 4, 4, 4, 4, 4, 4}},       {'U', {17, 17, 17, 17, 17, 17, 14}}, {'V', {17, 17, 17, 17, 17, 10, 4}},
        {'W', {17, 17, 17, 21, 21, 21, 10}}, {'X', {17, 17, 10, 4, 10, 17, 17}}, {'Y', {17, 17, 10, 4, 4, 4, 4}},
        {'Z', {31, 1, 2, 4, 8, 16, 31}},
    };
    return f;
}

class Canvas {
  public:
    Canvas(int w, int h) : m_w(w), m_h(h), m_rgb(static_cast<size_t>(w) * h * 3, 255) {}
    void set(int x, int y, const Rgb& c) {
        if (x < 0 || y < 0 || x >= m_w || y >= m_h) return;
        for (int k = 0; k < 3; ++k)
            m_rgb[(static_cast<size_t>(y) * m_w + x) * 3 + k] = static_cast<uint8_t>(std::lround(255 * std::clamp(c[k], 0.0, 1.0)));
    }
    void line(double x0, double y0, double x1, double y1, const Rgb& c, int width = 1) {
        int steps = static_cast<int>(std::max(std::abs(x1 - x0), std::abs(y1 - y0))) + 1;
        for (int i = 0; i <= steps; ++i) {
            double t = double(i) / steps;
            int x = static_cast<int>(std::lround(x0 + t * (x1 - x0))), y = static_cast<int>(std::lround(y0 + t * (y1 - y0)));
            for (int dx = 0; dx < width; ++dx)
                for (int dy = 0; dy < width; ++dy) set(x + dx, y + dy, c);
        }
    }
    void text(int x, int y, const std::string& s, const Rgb& c = Rgb(0.0)) {
        for (char ch : s) {
            auto it = font().find(static_cast<char>(std::toupper(static_cast<unsigned char>(ch))));
            if (it != font().end())
                for (int r = 0; r < 7; ++r)
                    for (int col = 0; col < 5; ++col)
                        if (it->second[r] & (16 >> col)) set(x + col, y + r, c);
            x += 6;
        }
    }
    const std::vector<uint8_t>& pixels() const { return m_rgb; }

  private:
    int m_w, m_h;
    std::vector<uint8_t> m_rgb;
};

}  // namespace

void writePlotPng(const std::string& path, const std::vector<PlotPanel>& panels) {
    const int pw = 460, ph = 340, left = 56, right = 12, top = 24, bottom = 44, legendH = 14;
    size_t legendRows = 0;
    for (const auto& p : panels) legendRows = std::max(legendRows, p.series.size());
    int h = ph + static_cast<int>(legendRows) * legendH;
    Canvas cv(pw * static_cast<int>(panels.size()), h);
    for (size_t pi = 0; pi < panels.size(); ++pi) {
        const PlotPanel& p = panels[pi];
        int ox = static_cast<int>(pi) * pw;
        double x0 = ox + left, x1 = ox + pw - right, y0 = top, y1 = ph - bottom;
        double xmin = 1e300, xmax = -1e300;
        for (const auto& s : p.series)
            for (const auto& pt : s.points)
                if (!p.logX || pt.x > 0) xmin = std::min(xmin, pt.x), xmax = std::max(xmax, pt.x);
        if (!(xmin < xmax)) xmin = 0.001, xmax = 1;
        auto fx = [&](double x) { return p.logX ? std::log10(std::max(x, 1e-300)) : x; };
        double lx0 = p.logX ? std::floor(fx(xmin)) : xmin, lx1 = p.logX ? std::ceil(fx(xmax)) : xmax;
        if (lx1 <= lx0) lx1 = lx0 + 1;
        auto X = [&](double x) { return x0 + (fx(x) - lx0) / (lx1 - lx0) * (x1 - x0); };
        auto Y = [&](double y) { return y1 - (std::clamp(y, p.yMin, p.yMax) - p.yMin) / (p.yMax - p.yMin) * (y1 - y0); };
        Rgb grey(0.8), black(0.0);
        // Grid and ticks.
        if (p.logX)
            for (int e = static_cast<int>(lx0); e <= static_cast<int>(lx1); ++e) {
                double xx = x0 + (e - lx0) / (lx1 - lx0) * (x1 - x0);
                cv.line(xx, y0, xx, y1, grey);
                std::string label = e >= 0 ? fmt::format("{:.0f}", std::pow(10.0, e)) : fmt::format("{:g}", std::pow(10.0, e));
                cv.text(static_cast<int>(xx) - 3 * static_cast<int>(label.size()), static_cast<int>(y1) + 5, label);
            }
        double step = (p.yMax - p.yMin) / 8;
        for (int k = 0; k <= 8; ++k) {
            double v = p.yMin + k * step, yy = Y(v);
            cv.line(x0, yy, x1, yy, std::abs(v) < 1e-12 ? Rgb(0.4) : grey);
            std::string label = fmt::format("{:+g}", v);
            cv.text(static_cast<int>(x0) - 6 * static_cast<int>(label.size()) - 4, static_cast<int>(yy) - 3, label);
        }
        cv.line(x0, y0, x0, y1, black);
        cv.line(x0, y1, x1, y1, black);
        cv.line(x1, y0, x1, y1, black);
        cv.line(x0, y0, x1, y0, black);
        cv.text(static_cast<int>(x0), 8, p.title);
        cv.text(static_cast<int>((x0 + x1) / 2) - 3 * static_cast<int>(p.xLabel.size()), static_cast<int>(y1) + 20, p.xLabel);
        cv.text(ox + 4, static_cast<int>(y0) - 14 + 0, p.yLabel);
        for (size_t si = 0; si < p.series.size(); ++si) {
            const auto& s = p.series[si];
            for (size_t k = 1; k < s.points.size(); ++k) {
                if (p.logX && (s.points[k - 1].x <= 0 || s.points[k].x <= 0)) continue;
                cv.line(X(s.points[k - 1].x), Y(s.points[k - 1].y), X(s.points[k].x), Y(s.points[k].y), s.color, 2);
            }
            int ly = ph + static_cast<int>(si) * legendH;
            cv.line(ox + left, ly + 3, ox + left + 18, ly + 3, s.color, 3);
            cv.text(ox + left + 24, ly, s.label);
        }
    }
    tonemap::writeDisplayImage(path, pw * static_cast<int>(panels.size()), h, cv.pixels());
}

}  // namespace rayrad::app
