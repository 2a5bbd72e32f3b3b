#include <scene/photometry.h>

#include <core/input_error.h>
#include <core/input_file.h>
#include <core/math.h>
#include <core/text.h>

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>

namespace rayrad::scene {

namespace {

constexpr double kDeg = kPi / 180;

/// Photometric files are small; anything beyond this is not one.
constexpr size_t kMaxPhotometryBytes = size_t(16) << 20;

bool near(double a, double b) { return std::abs(a - b) < 1e-6; }

/// Linear interpolation in a sorted table; 0 outside [xs.front(), xs.back()].
double interpolate(const std::vector<double>& xs, const std::vector<double>& ys, double x) {
    if (xs.size() == 1) return near(x, xs[0]) ? ys[0] : 0.0;
    if (x < xs.front() - 1e-9 || x > xs.back() + 1e-9) return 0.0;
    auto hi = std::upper_bound(xs.begin(), xs.end(), x);
    if (hi == xs.end()) return ys.back();
    if (hi == xs.begin()) return ys.front();
    const size_t j = static_cast<size_t>(hi - xs.begin());
    const double t = (x - xs[j - 1]) / (xs[j] - xs[j - 1]);
    return ys[j - 1] + t * (ys[j] - ys[j - 1]);
}

/// ∫ I(θ) w(θ) dθ over the table, I linear between the angles (degrees), exactly:
/// w = sin θ (type C, θ = γ) or cos θ (types A/B, θ = V).
double planeIntegral(const std::vector<double>& angles, const std::vector<double>& values, bool sine) {
    double sum = 0;
    for (size_t i = 0; i + 1 < angles.size(); ++i) {
        const double a = angles[i] * kDeg, b = angles[i + 1] * kDeg;
        if (b <= a) continue;
        const double slope = (values[i + 1] - values[i]) / (b - a), c0 = values[i] - slope * a;
        // sin: ∫ (c0 + sθ) sin θ = −(c0 + sθ) cos θ + s sin θ; cos: (c0 + sθ) sin θ + s cos θ.
        auto F = [&](double t) {
            return sine ? -(c0 + slope * t) * std::cos(t) + slope * std::sin(t)
                        : (c0 + slope * t) * std::sin(t) + slope * std::cos(t);
        };
        sum += F(b) - F(a);
    }
    return sum;
}

}  // namespace

std::string Photometry::symmetry() const {
    if (horizontal.size() == 1) return "rotational (one plane)";
    const double lo = horizontal.front(), hi = horizontal.back();
    if (type != PhotometricType::C) return near(lo, 0) ? "bilateral (0–90, mirrored)" : "none";
    if (near(lo, 0) && near(hi, 90)) return "quadrant (0–90)";
    if (near(lo, 0) && near(hi, 180)) return "bilateral (0–180)";
    if (near(lo, 90) && near(hi, 270)) return "bilateral (90–270)";
    return "none (full circle)";
}

/// The stored horizontal angle that holds the light at horizontal angle h (degrees).
static double unfoldHorizontal(const Photometry& p, double h) {
    const double lo = p.horizontal.front(), hi = p.horizontal.back();
    if (p.type != PhotometricType::C) return near(lo, 0) ? std::abs(h) : h;
    h = std::fmod(h, 360.0);
    if (h < 0) h += 360;
    if (near(lo, 0) && near(hi, 90)) return h <= 90 ? h : h <= 180 ? 180 - h : h <= 270 ? h - 180 : 360 - h;
    if (near(lo, 0) && near(hi, 180)) return h <= 180 ? h : 360 - h;
    if (near(lo, 90) && near(hi, 270)) return h >= 90 && h <= 270 ? h : h < 90 ? 180 - h : 540 - h;
    return h;
}

double Photometry::intensity(double verticalDeg, double horizontalDeg) const {
    if (candela.empty()) return 0;
    double v = verticalDeg;
    if (type != PhotometricType::C && near(vertical.front(), 0)) v = std::abs(v);  // symmetric about the horizontal
    auto plane = [&](size_t h) { return interpolate(vertical, candela[h], v); };
    if (horizontal.size() == 1) return plane(0);
    const double h = unfoldHorizontal(*this, horizontalDeg);
    if (type == PhotometricType::C && h > horizontal.back() && near(horizontal.front(), 0)) {
        // A full circle stored without its 360° plane (C0 … C345): wrap to C0.
        const double t = (h - horizontal.back()) / (360 - horizontal.back());
        return (1 - t) * plane(horizontal.size() - 1) + t * plane(0);
    }
    if (h < horizontal.front() - 1e-9 || h > horizontal.back() + 1e-9) return 0.0;
    // The two stored planes around h, then linear between them.
    auto hi = std::upper_bound(horizontal.begin(), horizontal.end(), h);
    if (hi == horizontal.end()) return plane(horizontal.size() - 1);
    if (hi == horizontal.begin()) return plane(0);
    const size_t j = static_cast<size_t>(hi - horizontal.begin());
    const double t = (h - horizontal[j - 1]) / (horizontal[j] - horizontal[j - 1]);
    return (1 - t) * plane(j - 1) + t * plane(j);
}

double Photometry::intensityToward(double x, double y, double z) const {
    auto deg = [](double radians) { return radians / kDeg; };
    switch (type) {
    case PhotometricType::C: return intensity(deg(std::acos(std::clamp(z, -1.0, 1.0))), deg(std::atan2(y, x)));
    case PhotometricType::B: return intensity(deg(std::asin(std::clamp(y, -1.0, 1.0))), deg(std::atan2(x, z)));
    case PhotometricType::A: return intensity(deg(std::asin(std::clamp(x, -1.0, 1.0))), deg(std::atan2(y, z)));
    }
    return 0;
}

double Photometry::integratedFlux() const {
    if (candela.empty()) return 0;
    const bool sine = type == PhotometricType::C;
    // Types A/B with only 0–90 stored vertically are symmetric about the horizontal plane.
    auto planeOf = [&](size_t h) {
        if (sine || !near(vertical.front(), 0)) return planeIntegral(vertical, candela[h], sine);
        return 2 * planeIntegral(vertical, candela[h], sine);
    };
    if (horizontal.size() == 1) return 2 * kPi * planeOf(0);  // rotational (type C)
    // The horizontal planes unfolded over the whole range, then the trapezoid rule.
    std::vector<double> angles;
    const double lo = horizontal.front(), hi = horizontal.back();
    for (double a : horizontal) {
        if (sine) {
            angles.push_back(a);
            if (near(lo, 0) && near(hi, 90)) angles.insert(angles.end(), {180 - a, 180 + a, 360 - a});
            else if (near(lo, 0) && near(hi, 180)) angles.push_back(360 - a);
            else if (near(lo, 90) && near(hi, 270)) angles.push_back(a <= 180 ? 180 - a : 540 - a);
        } else {
            angles.push_back(a);
            if (near(lo, 0)) angles.push_back(-a);
        }
    }
    if (sine) angles.push_back(360);  // close the circle (C360 = C0)
    std::sort(angles.begin(), angles.end());
    angles.erase(std::unique(angles.begin(), angles.end(), near), angles.end());
    double sum = 0, previous = 0;
    for (size_t i = 0; i < angles.size(); ++i) {
        // The plane at this angle: exact stored planes only (the unfolding maps onto them).
        const double stored = sine && angles[i] >= 360 - 1e-9 ? unfoldHorizontal(*this, 0.0) : unfoldHorizontal(*this, angles[i]);
        double value;
        auto it = std::find_if(horizontal.begin(), horizontal.end(), [&](double a) { return near(a, stored); });
        if (it != horizontal.end()) {
            value = planeOf(static_cast<size_t>(it - horizontal.begin()));
        } else {  // a full circle without its 360° plane: the wrap is C0
            value = planeOf(0);
        }
        if (i > 0) sum += 0.5 * (value + previous) * (angles[i] - angles[i - 1]) * kDeg;
        previous = value;
    }
    return sum;
}

Photometry::Peak Photometry::peak() const {
    Peak best;
    for (size_t h = 0; h < candela.size(); ++h)
        for (size_t v = 0; v < candela[h].size(); ++v)
            if (candela[h][v] > best.candela) best = {candela[h][v], vertical[v], horizontal[h]};
    return best;
}

bool isPhotometricFile(const std::string& path) {
    const std::string ext = lowerExtension(path);
    return ext == ".ies" || ext == ".ldt";
}

Photometry readPhotometry(const std::string& path) {
    if (!isPhotometricFile(path))
        throw InputError(placeMessage(path, "", "unknown photometric file type '" + lowerExtension(path) + "' (use .ies or .ldt)"));
    const std::string text = readInputFile(path, "photometric file", kMaxPhotometryBytes);
    return lowerExtension(path) == ".ies" ? parseIes(text, path) : parseLdt(text, path);
}

}  // namespace rayrad::scene
