#include <scene/daylight/perez.h>

#include <algorithm>
#include <cmath>

namespace rayrad::scene {

namespace {

/// Upper bounds of the eight clearness bins (Perez 1990 table 1; the last is open).
constexpr double kClearnessBins[7] = {1.065, 1.230, 1.500, 1.950, 2.800, 4.500, 6.200};

/// Perez, Seals & Michalsky 1993, table 1: per clearness bin, a1 … a4, b1 … b4, c1 … c4,
/// d1 … d4, e1 … e4; a parameter x = x1 + x2 Z + Δ (x3 + x4 Z), Z the sun's zenith angle
/// (rad), except c and d in the first bin (see perezCoefficients).
constexpr double kDistribution[8][20] = {
    {1.3525, -0.2576, -0.2690, -1.4366, -0.7670, 0.0007, 1.2734, -0.1233, 2.8000, 0.6004,  //
     1.2375, 1.0000, 1.8734, 0.6297, 0.9738, 0.2809, 0.0356, -0.1246, -0.5718, 0.9938},
    {-1.2219, -0.7730, 1.4148, 1.1016, -0.2054, 0.0367, -3.9128, 0.9156, 6.9750, 0.1774,  //
     6.4477, -0.1239, -1.5798, -0.5081, -1.7812, 0.1080, 0.2624, 0.0672, -0.2190, -0.4285},
    {-1.1000, -0.2515, 0.8952, 0.0156, 0.2782, -0.1812, -4.5000, 1.1766, 24.7219, -13.0812,  //
     -37.7000, 34.8438, -5.0000, 1.5218, 3.9229, -2.6204, -0.0156, 0.1597, 0.4199, -0.5562},
    {-0.5484, -0.6654, -0.2672, 0.7117, 0.7234, -0.6219, -5.6812, 2.6297, 33.3389, -18.3000,  //
     -62.2500, 52.0781, -3.5000, 0.0016, 1.1477, 0.1062, 0.4659, -0.3296, -0.0876, -0.0329},
    {-0.6000, -0.3566, -2.5000, 2.3250, 0.2937, 0.0496, -5.6812, 1.8415, 21.0000, -4.7656,  //
     -21.5906, 7.2492, -3.5000, -0.1554, 1.4062, 0.3988, 0.0032, 0.0766, -0.0656, -0.1294},
    {-1.0156, -0.3670, 1.0078, 1.4051, 0.2875, -0.5328, -3.8500, 3.3750, 14.0000, -0.9999,  //
     -7.1406, 7.5469, -3.4000, -0.1078, -1.0750, 1.5702, -0.0672, 0.4016, 0.3017, -0.4844},
    {-1.0000, 0.0211, 0.5025, -0.5119, -0.3000, 0.1922, 0.7023, -1.6317, 19.0000, -5.0000,  //
     1.2438, -1.9094, -4.0000, 0.0250, 0.3844, 0.2656, 1.0468, -0.3788, -2.4517, 1.4656},
    {-1.0500, 0.0289, 0.4260, 0.3590, -0.3250, 0.1156, 0.7781, 0.0025, 31.0625, -14.5000,  //
     -46.1148, 55.3750, -7.2312, 0.4050, 13.3500, 0.6234, 1.5000, -0.6426, 1.8564, 0.5636},
};

/// Perez 1990 table 4: luminous efficacy (lm/W) of the diffuse light, a + b W + c cos Z +
/// d ln Δ (eq. 7), and of the direct beam, max(0, a + b W + c exp(5.73 Z − 5) + d Δ) (eq. 8).
struct Efficacy {
    double a, b, c, d;
};
constexpr Efficacy kDiffuseEfficacy[8] = {
    {97.24, -0.46, 12.00, -8.91},  {107.22, 1.15, 0.59, -3.95},   {104.97, 2.96, -5.53, -8.77},
    {102.39, 5.59, -13.95, -13.90}, {100.71, 5.94, -22.75, -23.74}, {106.42, 3.83, -36.15, -28.83},
    {141.88, 1.90, -53.24, -14.03}, {152.23, 0.35, -45.27, -7.98},
};
constexpr Efficacy kDirectEfficacy[8] = {
    {57.20, -4.55, -2.98, 117.12}, {98.99, -3.46, -1.21, 12.38},  {109.83, -4.90, -1.71, -8.81},
    {110.34, -5.84, -1.99, -4.56}, {106.36, -3.97, -1.75, -6.16}, {107.19, -1.25, -1.51, -26.73},
    {105.75, 0.77, -1.26, -34.44}, {101.18, 1.58, -1.10, -8.29},
};

/// The solar constant, W/m², and the Earth–Sun distance factor (I₀ / 1367) on a day of
/// the year (Spencer 1971; 1 for day 0).
constexpr double kSolarConstant = 1367;
double eccentricity(int dayOfYear) {
    if (dayOfYear <= 0) return 1.0;
    const double g = 2 * kPi * (dayOfYear - 1) / 365.0;
    return 1.00011 + 0.034221 * std::cos(g) + 0.00128 * std::sin(g) + 0.000719 * std::cos(2 * g) +
           0.000077 * std::sin(2 * g);
}

/// ε, Δ and the bin from irradiances (W/m²), Perez 1990 eqs. 1 and 2.
void clearnessAndBrightness(PerezSky& s, const PerezConditions& c) {
    const double z = c.sunZenithRad, k = 1.041 * z * z * z;
    const double d = s.diffuseHorizontalIrradiance, i = s.directNormalIrradiance;
    s.clearness = d > 0 ? ((d + i) / d + k) / (1 + k) : 12.0;
    s.clearness = std::clamp(s.clearness, 1.0, 12.0);
    // Δ within the range the models were fitted to (0.01 … 0.6).
    s.brightness = std::clamp(d * relativeAirMass(z) / (kSolarConstant * eccentricity(c.dayOfYear)), 0.01, 0.6);
    s.bin = static_cast<int>(std::upper_bound(std::begin(kClearnessBins), std::end(kClearnessBins), s.clearness) -
                             std::begin(kClearnessBins));
}

double diffuseEfficacy(const PerezSky& s, const PerezConditions& c, double water) {
    const Efficacy& e = kDiffuseEfficacy[s.bin];
    return e.a + e.b * water + e.c * std::cos(c.sunZenithRad) + e.d * std::log(s.brightness);
}

double directEfficacy(const PerezSky& s, const PerezConditions& c, double water) {
    const Efficacy& e = kDirectEfficacy[s.bin];
    return std::max(0.0, e.a + e.b * water + e.c * std::exp(5.73 * c.sunZenithRad - 5) + e.d * s.brightness);
}

/// The distribution's a … e (Perez 1993 eqs. 6–8). In the partly cloudy bins (1.065 < ε
/// < 2.8) Δ is taken as at least 0.2, where the fit has data.
CieSkyParameters perezCoefficients(const PerezSky& s, double z) {
    const double* x = kDistribution[s.bin];
    double delta = s.brightness;
    if (s.clearness > 1.065 && s.clearness < 2.8) delta = std::max(delta, 0.2);
    auto linear = [&](int k) { return x[4 * k] + x[4 * k + 1] * z + delta * (x[4 * k + 2] + x[4 * k + 3] * z); };
    CieSkyParameters p{linear(0), linear(1), linear(2), linear(3), linear(4)};
    if (s.bin == 0) {
        p.c = std::exp(std::pow(delta * (x[8] + x[9] * z), x[10])) - x[11];
        p.d = -std::exp(delta * (x[12] + x[13] * z)) + x[14] + delta * x[15];
    }
    return p;
}

}  // namespace

double relativeAirMass(double zenithRad) {
    const double z = std::min(zenithRad, kPi / 2);
    return 1 / (std::cos(z) + 0.15 * std::pow(93.885 - z * 180 / kPi, -1.253));
}

PerezSky perezFromIrradiance(double directNormal, double diffuseHorizontal, const PerezConditions& c) {
    PerezSky s;
    s.directNormalIrradiance = directNormal;
    s.diffuseHorizontalIrradiance = diffuseHorizontal;
    clearnessAndBrightness(s, c);
    const double water = std::exp(0.07 * c.dewPointC - 0.075);  // cm
    s.diffuseHorizontalIlluminance = diffuseHorizontal * diffuseEfficacy(s, c, water);
    s.directNormalIlluminance = directNormal * directEfficacy(s, c, water);
    s.coefficients = perezCoefficients(s, c.sunZenithRad);
    return s;
}

PerezSky perezFromIlluminance(double directNormal, double diffuseHorizontal, const PerezConditions& c) {
    // Start from the solar constant's efficacy (127.5 klx / 1367 W/m²), then D = E_dh / K_d(ε, Δ)
    // and I = E_n / K_n(ε, Δ) until they settle.
    const double water = std::exp(0.07 * c.dewPointC - 0.075);
    constexpr double kStart = 127500.0 / kSolarConstant;  // lm/W
    PerezSky s;
    s.diffuseHorizontalIrradiance = diffuseHorizontal / kStart;
    s.directNormalIrradiance = directNormal / kStart;
    for (int round = 0; round < 20; ++round) {
        clearnessAndBrightness(s, c);
        const double kd = diffuseEfficacy(s, c, water), kn = directEfficacy(s, c, water);
        const double d = kd > 0 ? diffuseHorizontal / kd : 0.0, i = kn > 0 ? directNormal / kn : 0.0;
        const bool settled =
            std::abs(d - s.diffuseHorizontalIrradiance) < 0.1 && std::abs(i - s.directNormalIrradiance) < 0.1;
        s.diffuseHorizontalIrradiance = d, s.directNormalIrradiance = i;
        if (settled) break;
    }
    clearnessAndBrightness(s, c);
    s.diffuseHorizontalIlluminance = diffuseHorizontal;
    s.directNormalIlluminance = directNormal;
    s.coefficients = perezCoefficients(s, c.sunZenithRad);
    return s;
}

}  // namespace rayrad::scene
