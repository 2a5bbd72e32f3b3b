// Image against image, in luminance: a least-squares exposure factor, relative errors,
// the RMS of log luminance, and SSIM on the display-encoded images (rayrad compare).
#pragma once

#include <core/hdr_image.h>

#include <array>
#include <string>
#include <vector>

namespace rayrad::tonemap {

/// A rectangle of pixels (top-left origin) with a name, for per-region figures.
struct Region {
    std::string name;
    int x = 0, y = 0, width = 0, height = 0;
};

/// The least-squares factor in log luminance, k minimising Σ (ln k L_a − ln L_b)² over the
/// region's pixels where both have light (L_b above 1 % of its mean): k = exp mean
/// ln(L_b / L_a). Every pixel counts alike, so a lamp's few bright pixels do not decide
/// it, and noise biases it little. 1 when there is no such pixel.
double exposureFactor(const HdrImage& a, const HdrImage& b, const Region& region);
/// The same over several regions together (a pixel in two counts twice).
double exposureFactor(const HdrImage& a, const HdrImage& b, const std::vector<Region>& regions);

/// Per-channel factors, each as exposureFactor (a white balance and exposure together).
std::array<double, 3> channelFactors(const HdrImage& a, const HdrImage& b, const Region& region);
std::array<double, 3> channelFactors(const HdrImage& a, const HdrImage& b, const std::vector<Region>& regions);

struct ErrorFigures {
    size_t pixels = 0;           ///< pixels counted (the reference b has light there)
    double meanRelPct = 0;       ///< mean of (L_a − L_b) / L_b, %
    double meanAbsRelPct = 0;    ///< mean |L_a − L_b| / L_b, %
    double medianAbsRelPct = 0;
    double p95AbsRelPct = 0;     ///< 95th percentile of |L_a − L_b| / L_b, %
    double rmsLog = 0;           ///< √mean ln²((L_a + ε) / (L_b + ε)), ε the floor below
    double ssim = 1;             ///< SSIM of the display-encoded luminance (1 = identical)
    double meanDeltaE2000 = 0;   ///< CIEDE2000 between the displayed colours (lcms2), mean
    double p95DeltaE2000 = 0;    ///< and 95th percentile
    double meanFlip = 0;         ///< ꟻLIP (tonemap/image_flip) between the displayed colours, mean over the region
};

/// CIEDE2000 colour difference of two CIELAB colours (Sharma, Wu & Dalal 2005; lcms2's
/// cmsCIE2000DeltaE with k_L = k_C = k_H = 1).
double deltaE2000(const std::array<double, 3>& lab1, const std::array<double, 3>& lab2);

/// The figures of `a` (already calibrated) against the reference `b` over a region: pixels
/// where b's luminance is at least `floor` × b's mean (darker ones make relative errors
/// meaningless). SSIM (Wang et al. 2004: 11 × 11 Gaussian window, σ 1.5, K1 0.01, K2 0.03)
/// on the sRGB-encoded luminance of both after one exposure (b's log-average → 0.18);
/// CIEDE2000 and ꟻLIP between the colours as a display shows them at that exposure (in
/// gamut, D65 white of luminance 1; ꟻLIP at 67 pixels per degree, over the region alone).
ErrorFigures compareImages(const HdrImage& a, const HdrImage& b, const Region& region, double floor = 0.01);

/// |L_a − L_b| / L_b in % per pixel (NaN where b has no light), for the difference map.
std::vector<double> relativeDifferencePct(const HdrImage& a, const HdrImage& b, double floor = 0.01);

/// sRGB-encoded values (8-bit files) to linear: the IEC 61966-2-1 curve.
HdrImage linearFromSrgb(const HdrImage& encoded);

}  // namespace rayrad::tonemap
