// Texture images as a TextureSource for the radiosity and the ray tracer, read through
// OpenImageIO's TextureSystem (cached, filtered) in the image module (tonemap/image_library.h).
#pragma once

#include <core/texture_source.h>

#include <memory>
#include <string>
#include <vector>

namespace rayrad::tonemap {

/// Opens every file (its header: size, channels, encoding); throws InputError naming a
/// file that is not an image OpenImageIO can read. 8- and 16-bit images are taken as
/// sRGB-encoded (PNG, JPEG, TIFF as people save them) and decoded to linear — into a
/// tiled, MIP-mapped float copy in a temporary directory that goes with the returned
/// object, so the filtering averages linear values; float images (EXR, HDR) are linear. One
/// channel is grey; a fourth (alpha) is ignored.
std::shared_ptr<TextureSource> openTextureImages(const std::vector<std::string>& files);

}  // namespace rayrad::tonemap
