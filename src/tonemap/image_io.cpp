#include <tonemap/image_io.h>

#include <core/input_error.h>
#include <core/output_file.h>
#include <core/text.h>

#include <tonemap/image_library.h>

#include <OpenColorIO/OpenColorABI.h>  // version macros only: nothing of the library is linked
#include <OpenImageIO/oiioversion.h>

namespace rayrad::tonemap {

bool isHdrFormat(const std::string& path) {
    return lowerExtension(path) == ".exr";
}

void checkImageFormat(const std::string& path) {
    std::string e = lowerExtension(path);
    if (e != ".exr" && e != ".png" && e != ".jpg" && e != ".jpeg")
        throw OutputError(placeMessage(path, "", "unknown image format '" + e + "' (use .exr, .png or .jpg)"));
}

std::string encodeExr(const std::string& path, const HdrImage& image, const std::string& description,
                      const std::vector<std::pair<std::string, std::string>>& attributes) {
    return imageLibrary().encodeExr(path, image, description, attributes);
}

std::string encodeDisplayImage(const std::string& path, int width, int height, const std::vector<uint8_t>& rgb8,
                               const std::string& description) {
    return imageLibrary().encodeDisplayImage(path, width, height, rgb8, description);
}

HdrImage readImage(const std::string& path, std::vector<std::pair<std::string, std::string>>* attributes) {
    return imageLibrary().readImage(path, attributes);
}

std::string libraryVersions() {
    return "OpenImageIO " OIIO_VERSION_STRING ", OpenColorIO " OCIO_VERSION
           " (loaded when an image is read or written)";
}

void writeExr(const std::string& path, const HdrImage& image, const std::string& description) {
    writeFileAtomically(path, encodeExr(path, image, description));
}

void writeDisplayImage(const std::string& path, int width, int height, const std::vector<uint8_t>& rgb8) {
    writeFileAtomically(path, encodeDisplayImage(path, width, height, rgb8));
}

}  // namespace rayrad::tonemap
