// Tone reproduction: world luminance (cd/m²) → display luminance, relative to the
// display's white. Luminance and chroma are kept apart: a pixel's RGB is scaled by
// L_d / L_w, then brought into the display's gamut toward the grey of the same luminance
// (never clipped per channel, so a bright red stays red instead of turning cream).
#pragma once

#include <core/hdr_image.h>

#include <optional>
#include <string>

namespace rayrad::tonemap {

enum class ToneOperator {
    Exposure,          ///< L_d = s L_w; s from --exposure (auto: log-average → 0.18)
    TumblinRushmeier,  ///< Stevens' brightness power law (Tumblin & Rushmeier 1993, as revised 1999)
    Ward,              ///< Ward 1994: a contrast-preserving scale factor
    Reinhard,          ///< Reinhard et al. 2002: the photographic operator, global form
};

struct ToneOptions {
    ToneOperator op = ToneOperator::Exposure;
    std::optional<double> worldAdaptation;    ///< L_wa, cd/m²; default: the image's log-average
    double displayMax = 80;                   ///< L_dmax, cd/m²: the display's white (sRGB's reference display, IEC 61966-2-1)
    std::optional<double> displayAdaptation;  ///< L_da, cd/m²; default L_dmax / 2
    double maxContrast = 100;                 ///< C_max, the display's contrast (Tumblin–Rushmeier)
    double key = 0.18;                        ///< a, the key (Reinhard)
    std::optional<double> white;              ///< L_white in key-scaled units (Reinhard); default the image's largest
};

/// "exposure", "tumblin-rushmeier", "ward", "reinhard"; throws InputError otherwise.
ToneOperator parseToneOperator(const std::string& name);
std::string toneOperatorName(ToneOperator op);

/// Throws InputError naming the option for a parameter that is not finite and positive
/// (the key at most 10, the contrast at least 1).
void checkToneOptions(const ToneOptions& options);

/// The log-average luminance exp(mean ln L) over the pixels with light, cd/m² (0 if none).
double logAverageLuminance(const HdrImage& image);

/// A luminance map fitted to one image.
class ToneCurve {
  public:
    /// `exposureScale`: s for the exposure operator (cd/m² → display-relative).
    ToneCurve(const HdrImage& image, const ToneOptions& options, double exposureScale);
    /// Display luminance relative to display white (1 = white; may exceed 1) for a world
    /// luminance in cd/m².
    double operator()(double worldLuminance) const;
    /// "ward: L_wa 54.2 cd/m², L_dmax 80 cd/m²" — for messages and image metadata.
    std::string describe() const;

  private:
    ToneOptions m_o;
    double m_scale = 1;                ///< exposure: s; Ward: sf / L_dmax
    double m_worldAdaptation = 0;      ///< L_wa
    double m_displayAdaptation = 0;    ///< L_da
    double m_exponent = 1, m_factor = 1;  ///< Tumblin–Rushmeier: (L_w / L_wa)^exponent · factor
    double m_white = 1;                ///< Reinhard: L_white
};

/// Linear display-relative RGB (the pixel's colour scaled by L_d / L_w) brought into
/// [0, 1]³ keeping its CIELAB hue: first by less chroma at the same lightness (down to
/// half its chroma), then, if it is still too bright, by scaling it down with half its
/// chroma. Never clipped per channel, so a bright red stays red; in-gamut colours are
/// returned unchanged.
Rgb toDisplayGamut(const Rgb& rgb);

}  // namespace rayrad::tonemap
