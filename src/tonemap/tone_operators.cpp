#include <tonemap/tone_operators.h>

#include <core/colour_space.h>
#include <core/input_error.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace rayrad::tonemap {

namespace {

/// The least part of its CIELAB chroma a colour keeps when the display cannot show it at
/// its lightness (see toDisplayGamut).
constexpr double kMinChroma = 0.5;

/// Tumblin–Rushmeier's γ(L), the exponent of Stevens' brightness power law at adaptation
/// luminance L (cd/m²): 2.655 above 100 cd/m², else 1.855 + 0.4 log10(L + 2.3·10⁻⁵)
/// (Tumblin, Hodgins & Guenter 1999, eq. for the revised operator).
double stevensGamma(double L) { return L > 100 ? 2.655 : 1.855 + 0.4 * std::log10(L + 2.3e-5); }

}  // namespace

ToneOperator parseToneOperator(const std::string& name) {
    if (name == "exposure") return ToneOperator::Exposure;
    if (name == "tumblin-rushmeier") return ToneOperator::TumblinRushmeier;
    if (name == "ward") return ToneOperator::Ward;
    if (name == "reinhard") return ToneOperator::Reinhard;
    throw InputError(placeMessage("", "--tonemap", "expected exposure, tumblin-rushmeier, ward or reinhard, got \"" + name + "\""));
}

std::string toneOperatorName(ToneOperator op) {
    switch (op) {
    case ToneOperator::Exposure: return "exposure";
    case ToneOperator::TumblinRushmeier: return "tumblin-rushmeier";
    case ToneOperator::Ward: return "ward";
    case ToneOperator::Reinhard: return "reinhard";
    }
    return "?";
}

void checkToneOptions(const ToneOptions& o) {
    auto check = [](const char* option, std::optional<double> v, double lo, double hi) {
        if (v && !(std::isfinite(*v) && *v >= lo && *v <= hi))
            throw InputError(placeMessage("", option, fmt::format("expected a number from {:g} to {:g}, got {}", lo, hi, *v)));
    };
    check("--world-adaptation", o.worldAdaptation, 1e-9, 1e12);
    check("--display-max", o.displayMax, 1e-3, 1e6);
    check("--display-adaptation", o.displayAdaptation, 1e-3, 1e6);
    check("--max-contrast", o.maxContrast, 1, 1e9);
    check("--key", o.key, 1e-4, 10);
    check("--white", o.white, 1e-6, 1e12);
}

double logAverageLuminance(const HdrImage& image) {
    double sumLog = 0;
    size_t n = 0;
    for (const auto& p : image.pixels) {
        const double y = luminance(p);
        if (y > 0 && std::isfinite(y)) sumLog += std::log(y), ++n;
    }
    return n == 0 ? 0.0 : std::exp(sumLog / static_cast<double>(n));
}

ToneCurve::ToneCurve(const HdrImage& image, const ToneOptions& o, double exposureScale) : m_o(o) {
    m_worldAdaptation = o.worldAdaptation.value_or(logAverageLuminance(image));
    if (!(m_worldAdaptation > 0)) m_worldAdaptation = 1;  // a black image: any scale
    m_displayAdaptation = o.displayAdaptation.value_or(o.displayMax / 2);
    switch (o.op) {
    case ToneOperator::Exposure: m_scale = exposureScale; break;
    case ToneOperator::Ward: {
        // sf = [(1.219 + (L_dmax/2)^0.4) / (1.219 + L_wa^0.4)]^2.5, L_d = sf L_w (cd/m²).
        const double sf = std::pow((1.219 + std::pow(o.displayMax / 2, 0.4)) / (1.219 + std::pow(m_worldAdaptation, 0.4)), 2.5);
        m_scale = sf / o.displayMax;
        break;
    }
    case ToneOperator::TumblinRushmeier: {
        // L_d = m L_da (L_w / L_wa)^(γ(L_wa)/γ(L_da)), m = C_max^((γ_wd − 1)/2),
        // γ_wd = γ(L_wa) / (1.855 + 0.4 log10 L_da).
        const double gw = stevensGamma(m_worldAdaptation), gd = stevensGamma(m_displayAdaptation);
        const double gwd = gw / (1.855 + 0.4 * std::log10(m_displayAdaptation));
        m_exponent = gw / gd;
        m_factor = std::pow(o.maxContrast, (gwd - 1) / 2) * m_displayAdaptation / o.displayMax;
        break;
    }
    case ToneOperator::Reinhard: {
        // L = a L_w / L̄_w; L_d = L (1 + L / L_white²) / (1 + L), L_white the largest L.
        m_scale = o.key / m_worldAdaptation;
        double largest = 0;
        for (const auto& p : image.pixels) {
            const double y = luminance(p);
            if (std::isfinite(y)) largest = std::max(largest, y * m_scale);
        }
        m_white = o.white.value_or(largest > 0 ? largest : 1.0);
        break;
    }
    }
}

double ToneCurve::operator()(double Lw) const {
    if (!(Lw > 0)) return 0;
    switch (m_o.op) {
    case ToneOperator::Exposure:
    case ToneOperator::Ward: return m_scale * Lw;
    case ToneOperator::TumblinRushmeier: return m_factor * std::pow(Lw / m_worldAdaptation, m_exponent);
    case ToneOperator::Reinhard: {
        const double L = m_scale * Lw;
        return L * (1 + L / (m_white * m_white)) / (1 + L);
    }
    }
    return 0;
}

std::string ToneCurve::describe() const {
    switch (m_o.op) {
    case ToneOperator::Exposure: return fmt::format("exposure: {:.4g} per cd/m²", m_scale);
    case ToneOperator::Ward:
        return fmt::format("ward: L_wa {:.4g} cd/m², L_dmax {:g} cd/m²", m_worldAdaptation, m_o.displayMax);
    case ToneOperator::TumblinRushmeier:
        return fmt::format("tumblin-rushmeier: L_wa {:.4g} cd/m², L_da {:g} cd/m², L_dmax {:g} cd/m², C_max {:g}",
                           m_worldAdaptation, m_displayAdaptation, m_o.displayMax, m_o.maxContrast);
    case ToneOperator::Reinhard:
        return fmt::format("reinhard: key {:g}, L_w average {:.4g} cd/m², L_white {:.4g}", m_o.key, m_worldAdaptation, m_white);
    }
    return "";
}

namespace {

/// CIE L*a*b* (D65 white) of linear Rec.709 RGB, and back: the space the gamut mapping
/// keeps hue and lightness in.
struct Lab {
    double L, a, b;
};
double labF(double t) { return t > 216.0 / 24389 ? std::cbrt(t) : (24389.0 / 27 * t + 16) / 116; }
double labFInverse(double f) { return f * f * f > 216.0 / 24389 ? f * f * f : (116 * f - 16) * 27 / 24389; }

Lab toLab(const Rgb& c) {
    const Vec3 xyz = rec709ToXyz(c);
    const double fx = labF(xyz.x / kD65WhiteX), fy = labF(xyz.y), fz = labF(xyz.z / kD65WhiteZ);
    return {116 * fy - 16, 500 * (fx - fy), 200 * (fy - fz)};
}

Rgb fromLab(const Lab& lab) {
    const double fy = (lab.L + 16) / 116, fx = fy + lab.a / 500, fz = fy - lab.b / 200;
    return xyzToRec709(Vec3(kD65WhiteX * labFInverse(fx), labFInverse(fy), kD65WhiteZ * labFInverse(fz)));
}

bool inGamut(const Rgb& c, double slack = 1e-9) {
    return std::min({c.r, c.g, c.b}) >= -slack && std::max({c.r, c.g, c.b}) <= 1 + slack;
}

Rgb clamped(Rgb c) {
    for (int k = 0; k < 3; ++k) c[k] = std::clamp(c[k], 0.0, 1.0);
    return c;
}

}  // namespace

Rgb toDisplayGamut(const Rgb& c) {
    if (!(luminance(c) > 0)) return Rgb(0.0);
    if (inGamut(c, 0)) return c;
    const Lab lab = toLab(c);
    auto withChroma = [&](double s) { return fromLab({lab.L, s * lab.a, s * lab.b}); };
    // 1. Less chroma at the same lightness and hue (CIELAB), down to kMinChroma of it.
    if (lab.L < 100 && inGamut(withChroma(kMinChroma))) {
        double lo = kMinChroma, hi = 1;  // lo in gamut, hi not
        for (int i = 0; i < 40; ++i) {
            const double mid = 0.5 * (lo + hi);
            (inGamut(withChroma(mid)) ? lo : hi) = mid;
        }
        return clamped(withChroma(lo));
    }
    // 2. Brighter than the display can show with that much chroma: keep kMinChroma of it
    // and scale the colour down (XYZ scaled: a* and b* scale alike, the hue is kept).
    Rgb kept = withChroma(kMinChroma);
    for (int k = 0; k < 3; ++k) kept[k] = std::max(kept[k], 0.0);  // no negative channel
    const double top = std::max({kept.r, kept.g, kept.b});
    return top > 0 ? clamped(kept / top) : Rgb(0.0);
}

}  // namespace rayrad::tonemap
