// The image module's entry: the ImageLibrary rayrad loads on first use (tonemap/image_library.h).
#include <image_module/display_views.h>
#include <image_module/image_files.h>
#include <image_module/text_drawing.h>
#include <image_module/texture_images.h>
#include <tonemap/image_library.h>

namespace rayrad::image_module {

namespace {

class OiioOcioLibrary final : public tonemap::ImageLibrary {
  public:
    std::string encodeExr(const std::string& path, const HdrImage& image, const std::string& description,
                          const tonemap::StringAttributes& attributes) const override {
        return image_module::encodeExr(path, image, description, attributes);
    }
    std::string encodeDisplayImage(const std::string& path, int width, int height, const std::vector<uint8_t>& rgb8,
                                   const std::string& description) const override {
        return image_module::encodeDisplayImage(path, width, height, rgb8, description);
    }
    HdrImage readImage(const std::string& path, tonemap::StringAttributes* attributes) const override {
        return image_module::readImage(path, attributes);
    }
    std::unique_ptr<TextureSource> openTextures(const std::vector<std::string>& files) const override {
        return std::make_unique<TextureImages>(files);
    }
    void drawText(std::vector<uint8_t>& rgb, int width, int height,
                  const std::vector<tonemap::TextLabel>& labels) const override {
        image_module::drawText(rgb, width, height, labels);
    }
    tonemap::ResolvedView resolveView(const std::string& configFile, const std::string& embeddedConfig,
                                      const std::string& display, const std::string& view) const override {
        return image_module::resolveView(configFile, embeddedConfig, display, view);
    }
    std::string versions() const override { return libraryVersions(); }
};

}  // namespace

}  // namespace rayrad::image_module

extern "C" __attribute__((visibility("default"))) const rayrad::tonemap::ImageLibrary* rayradImageLibrary() {
    static const rayrad::image_module::OiioOcioLibrary library;
    return &library;
}
