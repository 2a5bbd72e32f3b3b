// Texture images as the pipeline sees them: linear RGB looked up by texture coordinates.
// The images are read elsewhere (tonemap/texture_images, through OpenImageIO), so the
// radiosity and the ray tracer need no image library.
#pragma once

#include <core/math.h>

namespace rayrad {

class TextureSource {
  public:
    virtual ~TextureSource() = default;
    /// Linear Rec.709 RGB of texture `index` at (u, v): v up (OBJ's convention), the image
    /// repeating outside [0, 1]², filtered over the footprint whose two axes (in texture
    /// coordinates) are `axisA` and `axisB` — MIP-mapped, anisotropic; zero axes: bilinear
    /// at the finest level. Safe to call from threads.
    virtual Rgb lookup(int index, double u, double v, const glm::dvec2& axisA, const glm::dvec2& axisB) const = 0;
    /// The decoded value of the texel at (u, v), no interpolation: for means, which then
    /// average texels exactly (bilinear interpolation of encoded values would not).
    virtual Rgb texel(int index, double u, double v) const = 0;
    /// The image's larger side in pixels (how finely a mean must sample it).
    virtual int resolution(int index) const = 0;
};

}  // namespace rayrad
