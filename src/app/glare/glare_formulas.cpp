#include <app/glare/glare_formulas.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace rayrad::app {

namespace {

constexpr double kDegrees = 180 / kPi;

}  // namespace

ViewFrame ViewFrame::from(const Vec3& direction, const Vec3& up) {
    ViewFrame f;
    f.forward = glm::normalize(direction);
    f.right = glm::normalize(glm::cross(f.forward, up));
    f.up = glm::cross(f.right, f.forward);
    return f;
}

double positionIndex(const Vec3& d) {
    if (d.z <= 0) return std::numeric_limits<double>::infinity();
    double sigma, tau;
    if (d.y >= 0) {
        sigma = std::acos(std::clamp(d.z, -1.0, 1.0)) * kDegrees;
        tau = std::atan2(std::abs(d.x), d.y) * kDegrees;
    } else {
        sigma = std::atan(std::sqrt(d.x * d.x + 1.15 * 1.15 * d.y * d.y) / d.z) * kDegrees;
        tau = 90;
    }
    const double lnP = (35.2 - 0.31889 * tau - 1.22 * std::exp(-2 * tau / 9)) * 1e-3 * sigma +
                       (21 + 0.26667 * tau - 0.002963 * tau * tau) * 1e-5 * sigma * sigma;
    return std::exp(lnP);
}

std::optional<double> unifiedGlareRating(double backgroundLuminance, const std::vector<GlareSource>& sources) {
    double sum = 0;
    for (const auto& s : sources)
        if (s.positionIndex <= kMaxPositionIndex) sum += s.term();
    if (!(sum > 0) || !(backgroundLuminance > 0)) return std::nullopt;
    return 8 * std::log10(0.25 / backgroundLuminance * sum);
}

double daylightGlareProbability(double verticalIlluminance, const std::vector<GlareSource>& sources) {
    const double ev = std::max(verticalIlluminance, 0.0);
    double sum = 0;
    if (ev > 0)
        for (const auto& s : sources) {
            const double p = std::min(s.positionIndex, kMaxPositionIndex);
            sum += s.luminance * s.luminance * s.solidAngle / (p * p) / std::pow(ev, 1.87);
        }
    double dgp = 5.87e-5 * ev + 9.18e-2 * std::log10(1 + sum) + 0.16;
    if (ev < 1000) {
        const double e = std::exp(0.024 * ev - 4);
        dgp *= e / (1 + e);
    }
    return std::min(dgp, 1.0);
}

std::string dgpClass(double dgp) {
    if (dgp < 0.35) return "imperceptible";
    if (dgp < 0.40) return "perceptible";
    if (dgp < 0.45) return "disturbing";
    return "intolerable";
}

}  // namespace rayrad::app
