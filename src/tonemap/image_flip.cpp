#include <tonemap/image_flip.h>

#include <core/colour_space.h>

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace rayrad::tonemap {

namespace {

constexpr double kQc = 0.7, kQf = 0.5, kPc = 0.4, kPt = 0.95;
constexpr double kFeatureWidth = 0.082;  ///< degrees: the edge and point detectors' scale

/// A single-channel image, row-major.
struct Plane {
    int width = 0, height = 0;
    std::vector<double> v;
    double at(int x, int y) const {  // replicated borders
        return v[static_cast<size_t>(std::clamp(y, 0, height - 1)) * width + std::clamp(x, 0, width - 1)];
    }
};

/// A (2r + 1)² kernel, row-major, k[(dy + r)(2r + 1) + dx + r].
struct Kernel {
    int r = 0;
    std::vector<double> k;
    double at(int dx, int dy) const { return k[static_cast<size_t>(dy + r) * (2 * r + 1) + dx + r]; }
};

/// out(x, y) = Σ in(x + dx, y + dy) · k(dx, dy) (correlation; borders replicated).
Plane filter(const Plane& in, const Kernel& kernel) {
    Plane out{in.width, in.height, std::vector<double>(in.v.size())};
    tbb::parallel_for(0, in.height, [&](int y) {
        for (int x = 0; x < in.width; ++x) {
            double sum = 0;
            for (int dy = -kernel.r; dy <= kernel.r; ++dy)
                for (int dx = -kernel.r; dx <= kernel.r; ++dx) sum += in.at(x + dx, y + dy) * kernel.at(dx, dy);
            out.v[static_cast<size_t>(y) * in.width + x] = sum;
        }
    });
    return out;
}

/// The contrast sensitivity of an opponent channel as a spatial kernel (the paper's eq. 3,
/// a1 √(π/b1) e^(−π² d²/b1) + a2 √(π/b2) e^(−π² d²/b2), d in degrees), normalised to sum 1;
/// every channel's kernel has the radius 3σ of the widest Gaussian of the three.
Kernel contrastSensitivity(double a1, double b1, double a2, double b2, double ppd) {
    constexpr double kWidestB = 0.04;  // b1 of the blue–yellow channel
    Kernel kernel;
    kernel.r = static_cast<int>(std::ceil(3 * std::sqrt(kWidestB / (2 * kPi * kPi)) * ppd));
    double sum = 0;
    for (int dy = -kernel.r; dy <= kernel.r; ++dy)
        for (int dx = -kernel.r; dx <= kernel.r; ++dx) {
            const double d2 = (dx * dx + dy * dy) / (ppd * ppd);
            const double g = a1 * std::sqrt(kPi / b1) * std::exp(-kPi * kPi * d2 / b1) +
                             a2 * std::sqrt(kPi / b2) * std::exp(-kPi * kPi * d2 / b2);
            kernel.k.push_back(g);
            sum += g;
        }
    for (double& g : kernel.k) g /= sum;
    return kernel;
}

/// The edge (first derivative of a Gaussian along x) or point (second derivative) detector,
/// its positive weights scaled to sum 1 and its negative ones to −1. The y detector is its
/// transpose.
Kernel featureDetector(bool edge, double ppd, bool transposed) {
    const double sd = 0.5 * kFeatureWidth * ppd;
    Kernel kernel;
    kernel.r = static_cast<int>(std::ceil(3 * sd));
    double positive = 0, negative = 0;
    for (int dy = -kernel.r; dy <= kernel.r; ++dy)
        for (int dx = -kernel.r; dx <= kernel.r; ++dx) {
            const int u = transposed ? dy : dx;  // the derivative's direction
            const double g = std::exp(-(dx * dx + dy * dy) / (2 * sd * sd));
            const double w = edge ? -u * g : (u * u / (sd * sd) - 1) * g;
            kernel.k.push_back(w);
            (w > 0 ? positive : negative) += w;
        }
    for (double& w : kernel.k) w = w > 0 ? w / positive : w < 0 ? w / -negative : 0.0;
    return kernel;
}

/// XYZ relative to the white (D65 as Rec.709's (1, 1, 1)) → YCxCz (Y = 116 y − 16, Cx =
/// 500 (x − y), Cz = 200 (y − z)) and back; XYZ → CIELAB with the same white.
const Vec3& white() {
    static const Vec3 w = rec709ToXyz(Rgb(1.0));
    return w;
}
Vec3 toYcxcz(const Rgb& linear) {
    const Vec3 n = rec709ToXyz(linear) / white();
    return {116 * n.y - 16, 500 * (n.x - n.y), 200 * (n.y - n.z)};
}
Rgb fromYcxcz(const Vec3& c) {
    const double y = (c.x + 16) / 116;
    return xyzToRec709(Vec3(y + c.y / 500, y, y - c.z / 200) * white());
}
Vec3 huntLab(const Rgb& linear) {
    const Vec3 n = rec709ToXyz(linear) / white();
    constexpr double d = 6.0 / 29;
    auto f = [&](double t) { return t > d * d * d ? std::cbrt(t) : t / (3 * d * d) + 4.0 / 29; };
    const double L = 116 * f(n.y) - 16, a = 500 * (f(n.x) - f(n.y)), b = 200 * (f(n.y) - f(n.z));
    return {L, 0.01 * L * a, 0.01 * L * b};  // Hunt: chroma scaled by 0.01 L
}
/// HyAB: |ΔL| + √(Δa² + Δb²).
double hyab(const Vec3& p, const Vec3& q) { return std::abs(p.x - q.x) + std::hypot(p.y - q.y, p.z - q.z); }

/// The colour pipeline's perceived colours: each opponent channel filtered, back to RGB
/// clamped to the display's [0, 1], then Hunt-adjusted CIELAB.
std::vector<Vec3> perceivedColours(const std::array<Plane, 3>& opponent, const std::array<Kernel, 3>& csf) {
    std::array<Plane, 3> filtered;
    for (int c = 0; c < 3; ++c) filtered[c] = filter(opponent[c], csf[c]);
    std::vector<Vec3> out(filtered[0].v.size());
    for (size_t i = 0; i < out.size(); ++i) {
        Rgb rgb = fromYcxcz(Vec3(filtered[0].v[i], filtered[1].v[i], filtered[2].v[i]));
        for (int c = 0; c < 3; ++c) rgb[c] = std::clamp(rgb[c], 0.0, 1.0);
        out[i] = huntLab(rgb);
    }
    return out;
}

}  // namespace

std::vector<double> flipErrorMap(const std::vector<Rgb>& reference, const std::vector<Rgb>& test, int width, int height,
                                 double ppd) {
    const size_t n = static_cast<size_t>(width) * height;
    // Opponent channels of both.
    std::array<Plane, 3> opponentRef, opponentTest;
    for (int c = 0; c < 3; ++c) {
        opponentRef[c] = {width, height, std::vector<double>(n)};
        opponentTest[c] = {width, height, std::vector<double>(n)};
    }
    for (size_t i = 0; i < n; ++i) {
        Rgb r = reference[i], t = test[i];
        for (int c = 0; c < 3; ++c) r[c] = std::clamp(r[c], 0.0, 1.0), t[c] = std::clamp(t[c], 0.0, 1.0);
        const Vec3 a = toYcxcz(r), b = toYcxcz(t);
        for (int c = 0; c < 3; ++c) opponentRef[c].v[i] = a[c], opponentTest[c].v[i] = b[c];
    }

    // Colour: the achromatic, red–green and blue–yellow sensitivities (the paper's Table 1).
    const std::array<Kernel, 3> csf = {contrastSensitivity(1, 0.0047, 0, 1e-5, ppd), contrastSensitivity(1, 0.0053, 0, 1e-5, ppd),
                                       contrastSensitivity(34.1, 0.04, 13.5, 0.025, ppd)};
    const std::vector<Vec3> labRef = perceivedColours(opponentRef, csf), labTest = perceivedColours(opponentTest, csf);
    const double cmax = std::pow(hyab(huntLab(Rgb(0, 1, 0)), huntLab(Rgb(0, 0, 1))), kQc);

    // Features of the normalised luminance (Y + 16) / 116.
    auto normalised = [&](const Plane& y) {
        Plane out = y;
        for (double& v : out.v) v = (v + 16) / 116;
        return out;
    };
    const Plane yRef = normalised(opponentRef[0]), yTest = normalised(opponentTest[0]);
    auto magnitude = [&](const Plane& y, bool edge) {
        const Plane fx = filter(y, featureDetector(edge, ppd, false)), fy = filter(y, featureDetector(edge, ppd, true));
        std::vector<double> m(n);
        for (size_t i = 0; i < n; ++i) m[i] = std::hypot(fx.v[i], fy.v[i]);
        return m;
    };
    const auto edgesRef = magnitude(yRef, true), edgesTest = magnitude(yTest, true);
    const auto pointsRef = magnitude(yRef, false), pointsTest = magnitude(yTest, false);

    std::vector<double> error(n);
    for (size_t i = 0; i < n; ++i) {
        const double e = std::pow(hyab(labRef[i], labTest[i]), kQc);
        const double colour = e < kPc * cmax ? kPt / (kPc * cmax) * e : kPt + (e - kPc * cmax) / (cmax - kPc * cmax) * (1 - kPt);
        const double feature = std::pow(std::max(std::abs(edgesRef[i] - edgesTest[i]), std::abs(pointsRef[i] - pointsTest[i])) /
                                            std::sqrt(2.0),
                                        kQf);
        error[i] = std::pow(colour, 1 - feature);
    }
    return error;
}

}  // namespace rayrad::tonemap
