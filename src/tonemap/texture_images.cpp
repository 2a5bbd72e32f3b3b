#include <tonemap/texture_images.h>

#include <core/colour_space.h>
#include <core/input_error.h>

#include <OpenImageIO/texture.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace rayrad::tonemap {

struct TextureImages::Impl {
    struct Image {
        OIIO::ustring name;
        int channels = 3;
        int resolution = 1;
        bool srgb = true;
    };
    OIIO::TextureSystem* system = nullptr;
    std::vector<Image> images;
};

TextureImages::TextureImages(const std::vector<std::string>& files) : m_impl(std::make_unique<Impl>()) {
    // A private TextureSystem (not the process-wide shared one), freed with this object.
    m_impl->system = OIIO::TextureSystem::create(/*shared=*/false);
    // Untiled, un-MIPmapped files (any PNG or JPEG) are read whole and MIP-mapped in memory.
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
        image.srgb = !(spec.format.is_floating_point() || space == "Linear" || space == "linear");
        m_impl->images.push_back(image);
    }
}

TextureImages::~TextureImages() {
    if (m_impl && m_impl->system) OIIO::TextureSystem::destroy(m_impl->system);
}

Rgb TextureImages::lookup(int index, double u, double v) const { return sample(index, u, v, true); }

Rgb TextureImages::texel(int index, double u, double v) const { return sample(index, u, v, false); }

Rgb TextureImages::sample(int index, double u, double v, bool bilinear) const {
    const Impl::Image& image = m_impl->images.at(static_cast<size_t>(index));
    OIIO::TextureOpt options;
    options.swrap = options.twrap = OIIO::TextureOpt::WrapPeriodic;
    options.mipmode = OIIO::TextureOpt::MipModeNoMIP;
    options.interpmode = bilinear ? OIIO::TextureOpt::InterpBilinear : OIIO::TextureOpt::InterpClosest;
    float rgb[3] = {0, 0, 0};
    // OIIO's t runs down the image; rayrad's v runs up it.
    if (!m_impl->system->texture(image.name, options, static_cast<float>(u), static_cast<float>(1 - v), 0, 0, 0, 0,
                                 image.channels, rgb))
        throw InputError(image.name.string() + ": texture lookup failed (" + m_impl->system->geterror() + ")");
    if (image.channels == 1) rgb[1] = rgb[2] = rgb[0];
    Rgb out(rgb[0], rgb[1], rgb[2]);
    if (image.srgb)
        for (int c = 0; c < 3; ++c) out[c] = srgbDecode(std::clamp(out[c], 0.0, 1.0));
    return out;
}

int TextureImages::resolution(int index) const { return m_impl->images.at(static_cast<size_t>(index)).resolution; }

}  // namespace rayrad::tonemap
