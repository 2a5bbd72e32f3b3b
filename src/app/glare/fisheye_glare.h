// Glare from a rendering: the glare sources in a 180° equidistant fisheye luminance image
// (as rayrad renders a "fisheye" camera), the vertical illuminance at the eye, UGR and DGP.
#pragma once

#include <app/glare/glare_formulas.h>
#include <core/hdr_image.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace rayrad::app {

/// How glare sources are told from the rest of the field.
struct GlareThreshold {
    std::optional<double> luminance;  ///< cd/m²: a pixel brighter than this is a source
    double factor = 5;                ///< else: this many times the field's mean luminance
};

/// Pixels brighter than this (cd/m²: the sun's disk, a bare lamp) make sources of their own,
/// not merged with the dimmer sources around them (evalglare's peak extraction): merged,
/// their L² ω would be spread over the larger region and underestimated.
constexpr double kPeakLuminance = 50000;

/// One pixel of the fisheye: its direction in the view frame (x right, y up, z along the
/// line of sight) and its solid angle, sr.
struct FisheyePixel {
    Vec3 direction{0, 0, 1};
    double solidAngle = 0;
};

/// The pixel (x, y) of a width × height equidistant fisheye (θ = r / R · 90°, R half the
/// smaller side, as raytrace/camera.cpp): nothing outside the circle. The solid angle of a
/// pixel is dω = (sin θ / θ) (π / 2R)² (the projection's area element).
std::optional<FisheyePixel> fisheyePixel(int width, int height, int x, int y);

struct FisheyeGlare {
    double threshold = 0;            ///< cd/m², the luminance sources were found above
    double meanLuminance = 0;        ///< of the field, solid-angle weighted, cd/m²
    double verticalIlluminance = 0;  ///< E_v = Σ L cos θ dω over the field, lx
    double sourceIlluminance = 0;    ///< the sources' part of E_v, lx
    double backgroundLuminance = 0;  ///< L_b = (E_v − the sources' part) / π, cd/m²
    /// Each connected region (8-neighbours) of pixels above the threshold, peaks
    /// (kPeakLuminance) and the rest apart: L its
    /// solid-angle-weighted mean, ω its solid angle, P at its centre, name "1", "2" ...
    /// largest L² ω / P² first.
    std::vector<GlareSource> sources;
    std::vector<int> sourceOfPixel;  ///< per pixel, the index into `sources`, or −1
    std::optional<double> ugr;       ///< over the sources (L_b as above)
    double dgp = 0;
};

/// Finds the sources and the figures. Throws InputError (naming `name`) when the image is
/// not a 180° fisheye as rayrad renders one — anything outside its circle is not black —
/// or its field is all black.
FisheyeGlare analyseFisheye(const HdrImage& image, const GlareThreshold& threshold, const std::string& name);

/// An 8-bit RGB picture, row-major, 3 bytes a pixel.
struct MarkedPicture {
    int width = 0, height = 0;
    std::vector<uint8_t> rgb;
};

/// The fisheye for the eye: its luminance in grey (white at the threshold), each source
/// tinted in its own colour and numbered, the `undrawn` sources (luminaires: the ray tracer
/// does not draw them) ringed where they are and labelled L1, L2 …, and a band below with
/// DGP, its class, UGR and E_v; width × (height + band).
MarkedPicture markGlareSources(const HdrImage& image, const FisheyeGlare& glare,
                               const std::vector<GlareSource>& undrawn = {});

}  // namespace rayrad::app
