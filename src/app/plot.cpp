#include <app/plot.h>

#include <tonemap/image_io.h>
#include <tonemap/text_drawing.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace rayrad::app {

namespace {

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
    /// Text whose vertical middle is at y, starting at x (or ending there, or centred).
    void text(int x, int y, const std::string& s, tonemap::TextLabel::Align align = tonemap::TextLabel::Align::Left) {
        m_labels.push_back({x, y, s, align, true, kTextSize});
    }
    /// The picture with its text set (DejaVu Sans through OpenImageIO).
    std::vector<uint8_t> pixels() const {
        std::vector<uint8_t> out = m_rgb;
        tonemap::drawText(out, m_w, m_h, m_labels);
        return out;
    }

  private:
    static constexpr int kTextSize = 12;  ///< px
    int m_w, m_h;
    std::vector<uint8_t> m_rgb;
    std::vector<tonemap::TextLabel> m_labels;
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
                cv.text(static_cast<int>(xx), static_cast<int>(y1) + 10, label, tonemap::TextLabel::Align::Centre);
            }
        double step = (p.yMax - p.yMin) / 8;
        for (int k = 0; k <= 8; ++k) {
            double v = p.yMin + k * step, yy = Y(v);
            cv.line(x0, yy, x1, yy, std::abs(v) < 1e-12 ? Rgb(0.4) : grey);
            std::string label = fmt::format("{:+g}", v);
            cv.text(static_cast<int>(x0) - 4, static_cast<int>(yy), label, tonemap::TextLabel::Align::Right);
        }
        cv.line(x0, y0, x0, y1, black);
        cv.line(x0, y1, x1, y1, black);
        cv.line(x1, y0, x1, y1, black);
        cv.line(x0, y0, x1, y0, black);
        cv.text(static_cast<int>((x0 + x1) / 2), 9, p.title, tonemap::TextLabel::Align::Centre);
        cv.text(static_cast<int>((x0 + x1) / 2), static_cast<int>(y1) + 27, p.xLabel, tonemap::TextLabel::Align::Centre);
        cv.text(static_cast<int>(x0) - 4, static_cast<int>(y0) - 10, p.yLabel, tonemap::TextLabel::Align::Right);
        for (size_t si = 0; si < p.series.size(); ++si) {
            const auto& s = p.series[si];
            for (size_t k = 1; k < s.points.size(); ++k) {
                if (p.logX && (s.points[k - 1].x <= 0 || s.points[k].x <= 0)) continue;
                cv.line(X(s.points[k - 1].x), Y(s.points[k - 1].y), X(s.points[k].x), Y(s.points[k].y), s.color, 2);
            }
            int ly = ph + static_cast<int>(si) * legendH;
            cv.line(ox + left, ly + 3, ox + left + 18, ly + 3, s.color, 3);
            cv.text(ox + left + 24, ly + 3, s.label);
        }
    }
    tonemap::writeDisplayImage(path, pw * static_cast<int>(panels.size()), h, cv.pixels());
}

}  // namespace rayrad::app
