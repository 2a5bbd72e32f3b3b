#include <tonemap/image_metrics.h>

#include <tonemap/image_flip.h>

#include <core/colour_space.h>
#include <tonemap/tone_operators.h>

#include <lcms2.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace rayrad::tonemap {

namespace {

template <class F>
void forEachPixel(const Region& r, F&& f) {
    for (int y = r.y; y < r.y + r.height; ++y)
        for (int x = r.x; x < r.x + r.width; ++x) f(x, y);
}

double meanLuminance(const HdrImage& img, const Region& r) {
    double sum = 0;
    size_t n = 0;
    forEachPixel(r, [&](int x, int y) {
        const double v = luminance(img.at(x, y));
        if (std::isfinite(v)) sum += v, ++n;
    });
    return n ? sum / static_cast<double>(n) : 0.0;
}

double percentile(std::vector<double> v, double p) {
    if (v.empty()) return 0;
    const size_t k = std::min(v.size() - 1, static_cast<size_t>(std::floor(p * static_cast<double>(v.size() - 1) + 0.5)));
    std::nth_element(v.begin(), v.begin() + static_cast<long>(k), v.end());
    return v[k];
}

double srgbEncode(double v) {
    v = std::clamp(v, 0.0, 1.0);
    return v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1 / 2.4) - 0.055;
}

/// SSIM over the region of two luminance rasters in [0, 1] (Wang, Bovik, Sheikh &
/// Simoncelli 2004): local means, variances and covariance under an 11 × 11 Gaussian
/// window (σ = 1.5, truncated at the region's edge and renormalised), averaged.
double ssim(const std::vector<double>& a, const std::vector<double>& b, int w, int h) {
    constexpr int R = 5;
    constexpr double C1 = 0.01 * 0.01, C2 = 0.03 * 0.03;
    double kernel[2 * R + 1];
    for (int i = -R; i <= R; ++i) kernel[i + R] = std::exp(-(i * i) / (2 * 1.5 * 1.5));
    double sum = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            double wsum = 0, ma = 0, mb = 0, aa = 0, bb = 0, ab = 0;
            for (int dy = -R; dy <= R; ++dy)
                for (int dx = -R; dx <= R; ++dx) {
                    const int u = x + dx, v = y + dy;
                    if (u < 0 || v < 0 || u >= w || v >= h) continue;
                    const double k = kernel[dx + R] * kernel[dy + R];
                    const double pa = a[static_cast<size_t>(v) * w + u], pb = b[static_cast<size_t>(v) * w + u];
                    wsum += k, ma += k * pa, mb += k * pb, aa += k * pa * pa, bb += k * pb * pb, ab += k * pa * pb;
                }
            ma /= wsum, mb /= wsum;
            const double va = aa / wsum - ma * ma, vb = bb / wsum - mb * mb, cov = ab / wsum - ma * mb;
            sum += ((2 * ma * mb + C1) * (2 * cov + C2)) / ((ma * ma + mb * mb + C1) * (va + vb + C2));
        }
    return w * h > 0 ? sum / (static_cast<double>(w) * h) : 1.0;
}

/// CIELAB (D65 white, Y = 1) of a display-relative linear Rec.709 colour, through lcms2.
cmsCIELab labOf(const Rgb& c) {
    static const cmsCIEXYZ white{kD65WhiteX, 1.0, kD65WhiteZ};
    const Vec3 v = rec709ToXyz(c);
    const cmsCIEXYZ xyz{v.x, v.y, v.z};
    cmsCIELab lab;
    cmsXYZ2Lab(&white, &lab, &xyz);
    return lab;
}

}  // namespace

double deltaE2000(const std::array<double, 3>& a, const std::array<double, 3>& b) {
    const cmsCIELab la{a[0], a[1], a[2]}, lb{b[0], b[1], b[2]};
    return cmsCIE2000DeltaE(&la, &lb, 1, 1, 1);
}

double exposureFactor(const HdrImage& a, const HdrImage& b, const std::vector<Region>& regions) {
    // Least squares in log luminance: min Σ (ln k + ln L_a − ln L_b)², so every pixel counts
    // alike (in absolute terms a lamp's few pixels would decide k) and noise biases it
    // little: k = exp mean ln(L_b / L_a).
    double sum = 0;
    size_t n = 0;
    for (const Region& r : regions) {
        const double threshold = 0.01 * meanLuminance(b, r);
        forEachPixel(r, [&](int x, int y) {
            const double la = luminance(a.at(x, y)), lb = luminance(b.at(x, y));
            if (lb > threshold && lb > 0 && la > 0 && std::isfinite(la)) sum += std::log(lb / la), ++n;
        });
    }
    return n ? std::exp(sum / static_cast<double>(n)) : 1.0;
}

double exposureFactor(const HdrImage& a, const HdrImage& b, const Region& region) {
    return exposureFactor(a, b, std::vector<Region>{region});
}

std::array<double, 3> channelFactors(const HdrImage& a, const HdrImage& b, const std::vector<Region>& regions) {
    std::array<double, 3> sum{};
    std::array<size_t, 3> n{};
    for (const Region& r : regions) {
        const double threshold = 0.01 * meanLuminance(b, r);
        forEachPixel(r, [&](int x, int y) {
            if (!(luminance(b.at(x, y)) > threshold)) return;
            for (int c = 0; c < 3; ++c) {
                const double pa = a.at(x, y)[c], pb = b.at(x, y)[c];
                if (pa > 0 && pb > 0 && std::isfinite(pa)) sum[c] += std::log(pb / pa), ++n[c];
            }
        });
    }
    std::array<double, 3> k{};
    for (int c = 0; c < 3; ++c) k[c] = n[c] ? std::exp(sum[c] / static_cast<double>(n[c])) : 1.0;
    return k;
}

std::array<double, 3> channelFactors(const HdrImage& a, const HdrImage& b, const Region& region) {
    return channelFactors(a, b, std::vector<Region>{region});
}

std::vector<double> relativeDifferencePct(const HdrImage& a, const HdrImage& b, double floor) {
    const Region whole{"", 0, 0, b.width, b.height};
    const double threshold = floor * meanLuminance(b, whole);
    std::vector<double> out(b.pixels.size(), std::numeric_limits<double>::quiet_NaN());
    for (size_t i = 0; i < out.size(); ++i) {
        const double la = luminance(a.pixels[i]), lb = luminance(b.pixels[i]);
        if (lb > threshold && lb > 0 && std::isfinite(la)) out[i] = 100 * std::abs(la - lb) / lb;
    }
    return out;
}

ErrorFigures compareImages(const HdrImage& a, const HdrImage& b, const Region& r, double floor) {
    ErrorFigures f;
    const double threshold = floor * meanLuminance(b, r);
    std::vector<double> absRel;
    double sumRel = 0, sumLog2 = 0;
    forEachPixel(r, [&](int x, int y) {
        const double la = luminance(a.at(x, y)), lb = luminance(b.at(x, y));
        if (!(lb > threshold && lb > 0) || !std::isfinite(la)) return;
        const double rel = (la - lb) / lb;
        sumRel += rel;
        absRel.push_back(std::abs(rel));
        const double d = std::log((std::max(la, 0.0) + threshold) / (lb + threshold));  // a dark a stays finite
        sumLog2 += d * d;
    });
    f.pixels = absRel.size();
    if (f.pixels > 0) {
        const double n = static_cast<double>(f.pixels);
        f.meanRelPct = 100 * sumRel / n;
        double sumAbs = 0;
        for (double v : absRel) sumAbs += v;
        f.meanAbsRelPct = 100 * sumAbs / n;
        f.medianAbsRelPct = 100 * percentile(absRel, 0.5);
        f.p95AbsRelPct = 100 * percentile(absRel, 0.95);
        f.rmsLog = std::sqrt(sumLog2 / n);
    }
    // SSIM on display-encoded luminance, one exposure for both (the reference's key).
    double sumLog = 0;
    size_t lit = 0;
    forEachPixel(r, [&](int x, int y) {
        const double lb = luminance(b.at(x, y));
        if (lb > 0 && std::isfinite(lb)) sumLog += std::log(lb), ++lit;
    });
    const double scale = lit ? 0.18 / std::exp(sumLog / static_cast<double>(lit)) : 1.0;
    std::vector<double> da, db;
    forEachPixel(r, [&](int x, int y) {
        const double la = luminance(a.at(x, y)), lb = luminance(b.at(x, y));
        da.push_back(srgbEncode(std::isfinite(la) ? la * scale : 0.0));
        db.push_back(srgbEncode(std::isfinite(lb) ? lb * scale : 0.0));
    });
    f.ssim = ssim(da, db, r.width, r.height);
    // CIEDE2000 between the displayed colours, same exposure.
    std::vector<double> de;
    forEachPixel(r, [&](int x, int y) {
        const Rgb& pa = a.at(x, y);
        if (!std::isfinite(luminance(pa))) return;  // outside an aligned image
        const cmsCIELab la = labOf(toDisplayGamut(pa * scale)), lb = labOf(toDisplayGamut(b.at(x, y) * scale));
        de.push_back(cmsCIE2000DeltaE(&la, &lb, 1, 1, 1));
    });
    if (!de.empty()) {
        double sum = 0;
        for (double v : de) sum += v;
        f.meanDeltaE2000 = sum / static_cast<double>(de.size());
        f.p95DeltaE2000 = percentile(de, 0.95);
    }
    // ꟻLIP between the same displayed colours (outside an aligned image: black).
    std::vector<Rgb> shownA, shownB;
    forEachPixel(r, [&](int x, int y) {
        const Rgb& pa = a.at(x, y);
        shownA.push_back(std::isfinite(luminance(pa)) ? toDisplayGamut(pa * scale) : Rgb(0.0));
        shownB.push_back(toDisplayGamut(b.at(x, y) * scale));
    });
    const auto flip = flipErrorMap(shownB, shownA, r.width, r.height);
    double flipSum = 0;
    for (double v : flip) flipSum += v;
    f.meanFlip = flip.empty() ? 0.0 : flipSum / static_cast<double>(flip.size());
    return f;
}

HdrImage linearFromSrgb(const HdrImage& encoded) {
    HdrImage out = encoded;
    for (auto& p : out.pixels)
        for (int c = 0; c < 3; ++c) p[c] = srgbDecode(p[c]);
    return out;
}

}  // namespace rayrad::tonemap
