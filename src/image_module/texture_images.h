// Texture images read through OpenImageIO's TextureSystem (cached, filtered), as a
// TextureSource for the radiosity and the ray tracer (tonemap/texture_images.h opens them).
#pragma once

#include <core/texture_source.h>

#include <memory>
#include <string>
#include <vector>

namespace rayrad::image_module {

class TextureImages : public TextureSource {
  public:
    /// Opens every file (its header: size, channels, encoding); throws InputError naming a
    /// file that is not an image OpenImageIO can read. 8- and 16-bit images are taken as
    /// sRGB-encoded (PNG, JPEG, TIFF as people save them) and decoded to linear — into a
    /// tiled, MIP-mapped float copy in a temporary directory that goes with this object, so
    /// the filtering averages linear values; float images (EXR, HDR) are linear. One
    /// channel is grey; a fourth (alpha) is ignored.
    explicit TextureImages(const std::vector<std::string>& files);
    ~TextureImages() override;

    Rgb lookup(int index, double u, double v, const glm::dvec2& axisA, const glm::dvec2& axisB) const override;
    Rgb texel(int index, double u, double v) const override;
    int resolution(int index) const override;

  private:
    /// OIIO's lookup; `axes` null: the texel at (u, v), no interpolation.
    Rgb sample(int index, double u, double v, const glm::dvec2* axes) const;
    struct Impl;
    std::unique_ptr<Impl> m_impl;
};

}  // namespace rayrad::image_module
