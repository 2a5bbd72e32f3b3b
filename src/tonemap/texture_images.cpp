#include <tonemap/texture_images.h>

#include <tonemap/image_library.h>

namespace rayrad::tonemap {

std::shared_ptr<TextureSource> openTextureImages(const std::vector<std::string>& files) {
    return imageLibrary().openTextures(files);
}

}  // namespace rayrad::tonemap
