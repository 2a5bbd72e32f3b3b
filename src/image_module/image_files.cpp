#include <image_module/image_files.h>

#include <core/input_error.h>
#include <core/output_file.h>

#include <OpenColorIO/OpenColorIO.h>
#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>

namespace OCIO = OCIO_NAMESPACE;

namespace rayrad::image_module {

namespace {

/// Encodes an image into memory through an OIIO IOProxy, the format by `path`'s extension.
std::string encode(const std::string& path, const OIIO::ImageSpec& spec, OIIO::TypeDesc format, const void* data) {
    auto out = OIIO::ImageOutput::create(path);
    if (!out) throw OutputError(placeMessage(path, "", "cannot write: " + OIIO::geterror()));
    std::vector<unsigned char> bytes;
    OIIO::Filesystem::IOVecOutput memory(bytes);
    // OIIO's convention: bool results, then has_error()/geterror() (which clears it).
    if (!out->set_ioproxy(&memory) || !out->open(path, spec) || !out->write_image(format, data) || !out->close()) {
        std::string why = out->has_error() ? out->geterror() : "unknown OpenImageIO error";
        throw OutputError(placeMessage(path, "", "cannot encode the image: " + why));
    }
    return std::string(bytes.begin(), bytes.end());
}

}  // namespace

std::string encodeExr(const std::string& path, const HdrImage& image, const std::string& description,
                      const std::vector<std::pair<std::string, std::string>>& attributes) {
    std::vector<float> buf(image.pixels.size() * 3);
    for (size_t i = 0; i < image.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) buf[3 * i + c] = static_cast<float>(image.pixels[i][c]);
    OIIO::ImageSpec spec(image.width, image.height, 3, OIIO::TypeDesc::FLOAT);
    spec.attribute("oiio:ColorSpace", "Linear");
    spec.attribute("ImageDescription", description);
    spec.attribute("Software", "rayrad");
    spec.attribute("rayrad:units", "cd/m^2 (absolute luminance), linear Rec.709 primaries, D65");
    // OpenEXR's standard attribute: luminance in cd/m² of RGB (1, 1, 1).
    spec.attribute("whiteLuminance", 1.0f);
    spec.attribute("compression", "zip");
    // No DateTime (OIIO would stamp the wall clock): the same scene, seed and options
    // give a bit-identical file. The file's own time says when it was written.
    spec.attribute("DateTime", "");
    for (const auto& [name, value] : attributes) spec.attribute(name, value);
    return encode(path, spec, OIIO::TypeDesc::FLOAT, buf.data());
}

std::string encodeDisplayImage(const std::string& path, int width, int height, const std::vector<uint8_t>& rgb8,
                               const std::string& description) {
    OIIO::ImageSpec spec(width, height, 3, OIIO::TypeDesc::UINT8);
    spec.attribute("oiio:ColorSpace", "sRGB");
    if (!description.empty()) spec.attribute("ImageDescription", description);
    spec.attribute("Software", "rayrad");
    spec.attribute("DateTime", "");  // bit-identical files, as for EXR
    return encode(path, spec, OIIO::TypeDesc::UINT8, rgb8.data());
}

HdrImage readImage(const std::string& path, std::vector<std::pair<std::string, std::string>>* attributes) {
    auto in = OIIO::ImageInput::open(path);
    if (!in) throw InputError(placeMessage(path, "", "cannot read image: " + OIIO::geterror()));
    const OIIO::ImageSpec& spec = in->spec();
    if (attributes)
        for (const auto& a : spec.extra_attribs)
            if (a.name().string().rfind("rayrad:", 0) == 0 && a.type() == OIIO::TypeDesc::STRING)
                attributes->emplace_back(a.name().string(), a.get_string());
    std::vector<float> buf(static_cast<size_t>(spec.width) * spec.height * spec.nchannels);
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, buf.data()))
        throw InputError(placeMessage(path, "", "cannot read image: " + in->geterror()));
    HdrImage img(spec.width, spec.height);
    for (size_t i = 0; i < img.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) img.pixels[i][c] = buf[i * spec.nchannels + std::min(c, spec.nchannels - 1)];
    return img;
}

std::string libraryVersions() {
    const int v = OIIO::openimageio_version();  // 10000 major + 100 minor + patch
    return "OpenImageIO " + std::to_string(v / 10000) + "." + std::to_string(v / 100 % 100) + "." +
           std::to_string(v % 100) + ", OpenColorIO " + OCIO::GetVersion();
}

}  // namespace rayrad::image_module
