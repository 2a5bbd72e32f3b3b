// The image libraries (OpenImageIO, OpenColorIO) behind one interface, implemented in a module
// of their own (src/image_module, librayrad_image.so) that is loaded the first time an image is
// read, written or drawn: Debian's OpenImageIO brings hundreds of shared libraries whose
// start-up a command that touches no image (--version, info, solve to a CSV) should not pay.
#pragma once

#include <core/hdr_image.h>
#include <core/texture_source.h>
#include <tonemap/text_drawing.h>

#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace rayrad::tonemap {

/// Scene-linear RGB → a display's encoded RGB (an OpenColorIO processor).
class DisplayProcessor {
  public:
    virtual ~DisplayProcessor() = default;
    /// In place, `pixels` packed RGB float triples.
    virtual void apply(float* rgb, size_t pixels) const = 0;
};

/// A display and view of an OpenColorIO config, checked to exist.
struct ResolvedView {
    std::string viewTransform;  ///< the view's transform ("ACES 1.0 SDR-video"), "" for a view that only encodes
    std::shared_ptr<const DisplayProcessor> processor;
};

using StringAttributes = std::vector<std::pair<std::string, std::string>>;

/// What rayrad asks of the image libraries. Errors are thrown as InputError (an image or
/// config that cannot be read) or OutputError (an image that cannot be encoded), naming
/// the file.
class ImageLibrary {
  public:
    virtual ~ImageLibrary() = default;
    /// See tonemap/image_io.h for the four image calls.
    virtual std::string encodeExr(const std::string& path, const HdrImage& image, const std::string& description,
                                  const StringAttributes& attributes) const = 0;
    virtual std::string encodeDisplayImage(const std::string& path, int width, int height,
                                           const std::vector<uint8_t>& rgb8, const std::string& description) const = 0;
    virtual HdrImage readImage(const std::string& path, StringAttributes* attributes) const = 0;
    /// Texture images as tonemap/texture_images.h describes them.
    virtual std::unique_ptr<TextureSource> openTextures(const std::vector<std::string>& files) const = 0;
    /// See tonemap/text_drawing.h.
    virtual void drawText(std::vector<uint8_t>& rgb, int width, int height,
                          const std::vector<TextLabel>& labels) const = 0;
    /// The display and view (empty: the config's defaults) of the config in `configFile`,
    /// or of `embeddedConfig` when that is empty.
    virtual ResolvedView resolveView(const std::string& configFile, const std::string& embeddedConfig,
                                     const std::string& display, const std::string& view) const = 0;
    /// "OpenImageIO 2.4.7, OpenColorIO 2.1.2": the versions the module runs with.
    virtual std::string versions() const = 0;
};

/// The image libraries, loaded on first use (thread-safe): $RAYRAD_IMAGE_MODULE, else
/// librayrad_image.so beside the program, where `cmake --install` puts it (lib/rayrad/), or
/// in the build tree.
/// Throws std::runtime_error when none loads.
const ImageLibrary& imageLibrary();

/// The name of the function the module exports: `const ImageLibrary* rayradImageLibrary()`.
constexpr const char* kImageLibraryEntry = "rayradImageLibrary";

}  // namespace rayrad::tonemap
