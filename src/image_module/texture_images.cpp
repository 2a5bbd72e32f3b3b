#include <image_module/texture_images.h>

#include <core/colour_space.h>
#include <core/input_error.h>

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/texture.h>
#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>

namespace rayrad::image_module {

struct TextureImages::Impl {
    struct Image {
        OIIO::ustring name;  ///< what the TextureSystem reads: the file, or its linear copy
        int channels = 3;
        int resolution = 1;
    };
    OIIO::TextureSystem* system = nullptr;
    std::vector<Image> images;
    std::string linearDirectory;  ///< the linear, MIP-mapped copies of encoded images ("" if none)
};

namespace {

/// A directory of our own under $TMPDIR (or /tmp), for the linear texture copies.
std::string makeTemporaryDirectory() {
    std::error_code error;
    const std::filesystem::path base = std::filesystem::temp_directory_path(error);
    if (error)
        throw InputError(std::string("$TMPDIR: no directory for the decoded textures (") + error.message() + ")");
    std::string pattern = (base / "rayrad-textures-XXXXXX").string();
    if (!mkdtemp(pattern.data()))
        throw InputError(pattern + ": cannot make a directory for the decoded textures (" + std::strerror(errno) + ")");
    return pattern;
}

/// Writes `file`'s first `channels` channels decoded from sRGB to linear, as a tiled,
/// MIP-mapped float OpenEXR texture at `copy`: filtering then averages light (linear
/// values), as the radiosity's mean reflectance does. Filtering the encoded values would
/// darken a fine pattern seen from afar (black and white checks: 0.21 instead of 0.5).
void writeLinearCopy(const std::string& file, int channels, const std::string& copy) {
    OIIO::ImageBuf linear(file);  // decoded in place once read: channels [0, channels) as float
    if (!linear.read(0, 0, 0, channels, /*force=*/true, OIIO::TypeDesc::FLOAT))
        throw InputError(file + ": cannot read the texture image (" + linear.geterror() + ")");
    for (OIIO::ImageBuf::Iterator<float> it(linear); !it.done(); ++it)
        for (int c = 0; c < channels; ++c) it[c] = static_cast<float>(srgbDecode(std::clamp<double>(it[c], 0.0, 1.0)));
    OIIO::ImageSpec config;
    config.format = OIIO::TypeDesc::FLOAT;
    config.attribute("wrapmodes", "periodic,periodic");  // MIP levels filtered across the seams, as the lookups wrap
    if (!OIIO::ImageBufAlgo::make_texture(OIIO::ImageBufAlgo::MakeTxTexture, linear, copy, config))
        throw InputError(file + ": cannot MIP-map the texture image (" + OIIO::geterror() + ")");
}

}  // namespace

TextureImages::TextureImages(const std::vector<std::string>& files) : m_impl(std::make_unique<Impl>()) {
    // A private TextureSystem (not the process-wide shared one), freed with this object.
    m_impl->system = OIIO::TextureSystem::create(/*shared=*/false);
    // Untiled, un-MIPmapped linear files (an EXR as saved) are read whole and MIP-mapped in memory.
    m_impl->system->attribute("automip", 1);
    for (const auto& file : files) {
        Impl::Image image;
        image.name = OIIO::ustring(file);
        OIIO::ImageSpec spec;
        if (!m_impl->system->get_imagespec(image.name, 0, spec)) {
            std::string error = m_impl->system->has_error() ? m_impl->system->geterror() : "unreadable";
            error = error.substr(0, error.find('\n'));  // one line, as every message
            throw InputError(file + ": not a texture image OpenImageIO can read (" + error + ")");
        }
        if (spec.nchannels < 1 || spec.width < 1 || spec.height < 1)
            throw InputError(file + ": a texture image needs at least one channel and one pixel");
        image.channels = spec.nchannels >= 3 ? 3 : 1;  // grey, or grey and alpha: the first channel
        image.resolution = std::max(spec.width, spec.height);
        const std::string space = spec.get_string_attribute("oiio:ColorSpace");
        const bool encoded = !(spec.format.is_floating_point() || space == "Linear" || space == "linear");
        if (!encoded) {
            // A float image can hold NaN and Inf, which would make a NaN reflectance and
            // a NaN solution: refused here, where the file can be named.
            OIIO::ImageBuf buffer(file);
            const auto stats = OIIO::ImageBufAlgo::computePixelStats(buffer);
            size_t bad = 0;
            for (size_t c = 0; c < stats.nancount.size(); ++c) bad += stats.nancount[c] + stats.infcount[c];
            if (bad > 0)
                throw InputError(fmt::format("{}: {} texel value(s) are not finite (NaN or Inf): a texture gives "
                                             "reflectances, numbers from 0 to 1",
                                             file, bad));
        }
        if (encoded) {
            // 8- and 16-bit images are sRGB-encoded: looked up through a linear copy.
            if (m_impl->linearDirectory.empty()) m_impl->linearDirectory = makeTemporaryDirectory();
            const std::string copy = fmt::format("{}/{}.exr", m_impl->linearDirectory, m_impl->images.size());
            writeLinearCopy(file, image.channels, copy);
            image.name = OIIO::ustring(copy);
        }
        m_impl->images.push_back(image);
    }
}

TextureImages::~TextureImages() {
    if (m_impl && m_impl->system) OIIO::TextureSystem::destroy(m_impl->system);
    if (m_impl && !m_impl->linearDirectory.empty()) {
        std::error_code ignored;  // a leftover temporary directory is not worth an exception in a destructor
        std::filesystem::remove_all(m_impl->linearDirectory, ignored);
    }
}

Rgb TextureImages::lookup(int index, double u, double v, const glm::dvec2& axisA, const glm::dvec2& axisB) const {
    const glm::dvec2 axes[2] = {axisA, axisB};
    return sample(index, u, v, axes);
}

Rgb TextureImages::texel(int index, double u, double v) const {
    return sample(index, u, v, nullptr);
}

Rgb TextureImages::sample(int index, double u, double v, const glm::dvec2* axes) const {
    const Impl::Image& image = m_impl->images.at(static_cast<size_t>(index));
    OIIO::TextureOpt options;
    options.swrap = options.twrap = OIIO::TextureOpt::WrapPeriodic;
    // A footprint: OIIO picks the MIP levels from the derivatives and filters along the
    // longer axis (anisotropic, up to 32:1), over linear values.
    options.mipmode = axes ? OIIO::TextureOpt::MipModeAniso : OIIO::TextureOpt::MipModeNoMIP;
    options.interpmode = axes ? OIIO::TextureOpt::InterpBilinear : OIIO::TextureOpt::InterpClosest;
    // OIIO's t runs down the image; rayrad's v runs up it (so dt = −dv).
    const float dsdx = axes ? static_cast<float>(axes[0].x) : 0.0f, dtdx = axes ? static_cast<float>(-axes[0].y) : 0.0f;
    const float dsdy = axes ? static_cast<float>(axes[1].x) : 0.0f, dtdy = axes ? static_cast<float>(-axes[1].y) : 0.0f;
    float rgb[3] = {0, 0, 0};
    if (!m_impl->system->texture(image.name, options, static_cast<float>(u), static_cast<float>(1 - v), dsdx, dtdx,
                                 dsdy, dtdy, image.channels, rgb))
        throw InputError(image.name.string() + ": texture lookup failed (" + m_impl->system->geterror() + ")");
    if (image.channels == 1) rgb[1] = rgb[2] = rgb[0];
    return Rgb(rgb[0], rgb[1], rgb[2]);
}

int TextureImages::resolution(int index) const {
    return m_impl->images.at(static_cast<size_t>(index)).resolution;
}

}  // namespace rayrad::image_module
