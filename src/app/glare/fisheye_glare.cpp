#include <app/glare/fisheye_glare.h>

#include <core/input_error.h>
#include <tonemap/text_drawing.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace rayrad::app {

namespace {

/// A source's sums over its pixels, as they are found.
struct SourceSums {
    double solidAngle = 0, luminanceOmega = 0, illuminance = 0;
    Vec3 direction{0.0};
};

/// Distinct tints for the sources, in order.
constexpr uint8_t kTints[][3] = {{230, 40, 40},  {40, 120, 230}, {40, 180, 60},  {240, 160, 20},
                                 {160, 60, 200}, {20, 190, 190}, {220, 80, 160}, {140, 140, 40}};

/// The sources: 8-connected regions of pixels above `threshold` (lum −1 outside the
/// field), the peaks (above kPeakLuminance) apart from the rest; `sourceOfPixel` gets each
/// pixel's region, or −1.
std::vector<SourceSums> findSources(const std::vector<double>& lum, int w, int h, double threshold,
                                    std::vector<int>& sourceOfPixel) {
    auto peak = [](double L) { return L > kPeakLuminance; };
    sourceOfPixel.assign(lum.size(), -1);
    std::vector<SourceSums> sums;
    std::vector<size_t> stack;
    for (size_t seed = 0; seed < lum.size(); ++seed) {
        if (lum[seed] <= threshold || sourceOfPixel[seed] >= 0) continue;
        const int id = static_cast<int>(sums.size());
        SourceSums s;
        stack.assign(1, seed);
        sourceOfPixel[seed] = id;
        while (!stack.empty()) {
            const size_t i = stack.back();
            stack.pop_back();
            const int x = static_cast<int>(i % w), y = static_cast<int>(i / w);
            const FisheyePixel p = *fisheyePixel(w, h, x, y);  // in the field: lum ≥ 0
            s.solidAngle += p.solidAngle;
            s.luminanceOmega += lum[i] * p.solidAngle;
            s.illuminance += lum[i] * p.direction.z * p.solidAngle;
            s.direction += p.solidAngle * p.direction;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int nx = x + dx, ny = y + dy;
                    if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
                    const size_t n = static_cast<size_t>(ny) * w + nx;
                    if (lum[n] > threshold && sourceOfPixel[n] < 0 && peak(lum[n]) == peak(lum[seed])) {
                        sourceOfPixel[n] = id;
                        stack.push_back(n);
                    }
                }
        }
        sums.push_back(s);
    }
    return sums;
}

}  // namespace

std::optional<FisheyePixel> fisheyePixel(int width, int height, int x, int y) {
    const double R = std::min(width, height) / 2.0;
    const double u = x + 0.5 - width / 2.0, v = height / 2.0 - (y + 0.5);
    const double r = std::hypot(u, v) / R;
    if (r > 1) return std::nullopt;
    const double theta = r * kPi / 2, phi = std::atan2(v, u);
    const double pixelAngle = kPi / (2 * R);
    FisheyePixel p;
    p.direction = Vec3(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
    p.solidAngle = (theta > 0 ? std::sin(theta) / theta : 1.0) * pixelAngle * pixelAngle;
    return p;
}

FisheyeGlare analyseFisheye(const HdrImage& image, const GlareThreshold& threshold, const std::string& name) {
    const int w = image.width, h = image.height;
    const double R = std::min(w, h) / 2.0;
    std::vector<double> lum(image.pixels.size(), -1);  // −1: outside the field
    double omega = 0, lOmega = 0;
    FisheyeGlare out;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const size_t i = static_cast<size_t>(y) * w + x;
            const double L = luminance(image.pixels[i]);
            if (!std::isfinite(L))
                throw InputError(placeMessage(name, fmt::format("pixel ({}, {})", x, y), "the luminance is not finite"));
            const auto p = fisheyePixel(w, h, x, y);
            if (!p) {
                // Beyond the circle (and its antialiased rim) a rayrad fisheye is black.
                const double r = std::hypot(x + 0.5 - w / 2.0, h / 2.0 - (y + 0.5)) / R;
                if (r > 1 + 1.5 / R && L != 0)
                    throw InputError(placeMessage(
                        name, fmt::format("pixel ({}, {})", x, y),
                        "not black outside the image's inscribed circle: the glare figures need a 180° equidistant "
                        "fisheye in cd/m², as rayrad renders a camera with \"projection\": \"fisheye\""));
                continue;
            }
            lum[i] = std::max(L, 0.0);
            omega += p->solidAngle;
            lOmega += lum[i] * p->solidAngle;
            out.verticalIlluminance += lum[i] * p->direction.z * p->solidAngle;
        }
    if (!(lOmega > 0)) throw InputError(placeMessage(name, "", "the fisheye's field is black: no light to judge"));
    out.meanLuminance = lOmega / omega;
    out.threshold = threshold.luminance ? *threshold.luminance : threshold.factor * out.meanLuminance;

    std::vector<SourceSums> sums = findSources(lum, w, h, out.threshold, out.sourceOfPixel);
    std::vector<GlareSource> found;
    for (const SourceSums& s : sums) {
        GlareSource g;
        g.solidAngle = s.solidAngle;
        g.luminance = s.luminanceOmega / s.solidAngle;
        g.direction = glm::normalize(s.direction);
        g.positionIndex = positionIndex(g.direction);
        found.push_back(g);
        out.sourceIlluminance += s.illuminance;
    }
    // Largest L² ω / P² first (DGP's P, held to 16: every source in the field is ranked).
    std::vector<int> order(found.size());
    std::iota(order.begin(), order.end(), 0);
    auto dgpTerm = [&](int k) {
        const double p = std::min(found[k].positionIndex, kMaxPositionIndex);
        return found[k].luminance * found[k].luminance * found[k].solidAngle / (p * p);
    };
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return dgpTerm(a) > dgpTerm(b); });
    std::vector<int> rank(found.size());
    for (size_t k = 0; k < order.size(); ++k) {
        rank[static_cast<size_t>(order[k])] = static_cast<int>(k);
        out.sources.push_back(found[static_cast<size_t>(order[k])]);
        out.sources.back().name = std::to_string(k + 1);
    }
    for (int& s : out.sourceOfPixel)
        if (s >= 0) s = rank[static_cast<size_t>(s)];
    out.backgroundLuminance = std::max(0.0, out.verticalIlluminance - out.sourceIlluminance) / kPi;
    out.ugr = unifiedGlareRating(out.backgroundLuminance, out.sources);
    out.dgp = daylightGlareProbability(out.verticalIlluminance, out.sources);
    return out;
}

MarkedPicture markGlareSources(const HdrImage& image, const FisheyeGlare& glare,
                               const std::vector<GlareSource>& undrawn) {
    constexpr int kBand = 64;  // px below the image for the figures
    MarkedPicture m;
    m.width = image.width;
    m.height = image.height + kBand;
    m.rgb.assign(static_cast<size_t>(m.width) * m.height * 3, 255);
    std::vector<double> sx(glare.sources.size()), sy(glare.sources.size()), n(glare.sources.size());
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const size_t i = static_cast<size_t>(y) * image.width + x;
            const double L = luminance(image.pixels[i]);
            // Grey: white at the threshold (a display gamma of 2.2 below it).
            const double g = std::pow(std::clamp(L / glare.threshold, 0.0, 1.0), 1 / 2.2);
            double rgb[3] = {255 * g, 255 * g, 255 * g};
            if (const int s = glare.sourceOfPixel[i]; s >= 0) {
                const auto& tint = kTints[static_cast<size_t>(s) % std::size(kTints)];
                for (int c = 0; c < 3; ++c) rgb[c] = 0.35 * rgb[c] + 0.65 * tint[c];
                sx[static_cast<size_t>(s)] += x;
                sy[static_cast<size_t>(s)] += y;
                n[static_cast<size_t>(s)] += 1;
            }
            for (int c = 0; c < 3; ++c) m.rgb[i * 3 + c] = static_cast<uint8_t>(std::lround(rgb[c]));
        }
    auto ring = [&](double cx, double cy, const uint8_t* tint) {
        for (int a = 0; a < 360; ++a)
            for (double radius : {9.0, 10.0}) {
                const int x = static_cast<int>(std::lround(cx + radius * std::cos(a * kPi / 180)));
                const int y = static_cast<int>(std::lround(cy + radius * std::sin(a * kPi / 180)));
                if (x < 0 || y < 0 || x >= image.width || y >= image.height) continue;
                for (int c = 0; c < 3; ++c) m.rgb[(static_cast<size_t>(y) * image.width + x) * 3 + c] = tint[c];
            }
    };
    // A ring around a source too small to see (the sun's disk is a pixel or two).
    for (size_t k = 0; k < glare.sources.size(); ++k)
        if (n[k] > 0 && n[k] <= 30) ring(sx[k] / n[k], sy[k] / n[k], kTints[k % std::size(kTints)]);
    std::vector<tonemap::TextLabel> labels;
    // The undrawn sources where the projection puts them: r = θ / 90° · R.
    const double R = std::min(image.width, image.height) / 2.0;
    constexpr uint8_t kLuminaireTint[3] = {255, 200, 0};
    for (size_t k = 0; k < undrawn.size(); ++k) {
        const Vec3& d = undrawn[k].direction;
        const double r = std::acos(std::clamp(d.z, -1.0, 1.0)) / (kPi / 2) * R, phi = std::atan2(d.y, d.x);
        const double cx = image.width / 2.0 + r * std::cos(phi) - 0.5, cy = image.height / 2.0 - r * std::sin(phi) - 0.5;
        ring(cx, cy, kLuminaireTint);
        labels.push_back({static_cast<int>(cx) + 14, static_cast<int>(cy), fmt::format("L{}", k + 1),
                          tonemap::TextLabel::Align::Left, true, 12});
    }
    for (size_t k = 0; k < glare.sources.size() && k < 9; ++k)
        if (n[k] > 0)
            labels.push_back({static_cast<int>(sx[k] / n[k]) + (n[k] > 30 ? 0 : 16), static_cast<int>(sy[k] / n[k]),
                              glare.sources[k].name,
                              tonemap::TextLabel::Align::Centre, true, 14});
    // Figures of any scale: whole numbers from 100 up, three digits below.
    auto figure = [](double v) { return v >= 100 ? fmt::format("{:.0f}", v) : fmt::format("{:.3g}", v); };
    labels.push_back({8, image.height + 18, fmt::format("DGP {:.2f} ({})", glare.dgp, dgpClass(glare.dgp)),
                      tonemap::TextLabel::Align::Left, false, 14});
    labels.push_back({8, image.height + 36,
                      fmt::format("UGR {}, Ev {} lx", glare.ugr ? fmt::format("{:.1f}", *glare.ugr) : std::string("-"),
                                  figure(glare.verticalIlluminance)),
                      tonemap::TextLabel::Align::Left, false, 13});
    labels.push_back({8, image.height + 54,
                      fmt::format("{} source{} above {} cd/m2 (white){}", glare.sources.size(),
                                  glare.sources.size() == 1 ? "" : "s", figure(glare.threshold),
                                  undrawn.empty() ? std::string()
                                                  : fmt::format("; {} luminaires ringed", undrawn.size())),
                      tonemap::TextLabel::Align::Left, false, 12});
    tonemap::drawText(m.rgb, m.width, m.height, labels);
    return m;
}

}  // namespace rayrad::app
