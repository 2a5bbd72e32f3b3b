#include <scene/daylight/glazing.h>

#include <algorithm>
#include <cmath>

namespace rayrad::scene {

namespace {
/// One pane's transmittance at incidence cosθ, internal transmittance `Ta` at normal incidence.
double paneTransmittance(double Ta, double cosTheta) {
    const double n = kGlazingIndex;
    const double cosI = std::clamp(cosTheta, 1e-9, 1.0);
    const double sinT = std::sqrt(1 - cosI * cosI) / n;
    const double cosT = std::sqrt(1 - sinT * sinT);
    const double rs = (cosI - n * cosT) / (cosI + n * cosT);
    const double rp = (cosT - n * cosI) / (cosT + n * cosI);
    const double T = std::pow(Ta, 1 / cosT);
    double sum = 0;
    for (double r : {rs * rs, rp * rp}) sum += (1 - r) * (1 - r) * T / (1 - r * r * T * T);
    return sum / 2;
}
}  // namespace

double glazingTransmittance(double normal, double cosTheta) {
    if (normal >= 1) return 1.0;
    if (cosTheta <= 0) return 0.0;
    // T_a from g(0) = (1 − R₀)² T_a / (1 − R₀² T_a²) = normal, the root in (0, 1].
    const double r0 = std::pow((kGlazingIndex - 1) / (kGlazingIndex + 1), 2);
    const double a = r0 * r0 * normal, b = (1 - r0) * (1 - r0);
    const double Ta = std::min(1.0, (-b + std::sqrt(b * b + 4 * a * normal)) / (2 * a));
    return normal * paneTransmittance(Ta, cosTheta) / paneTransmittance(Ta, 1.0);
}

}  // namespace rayrad::scene
