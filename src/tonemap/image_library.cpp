#include <tonemap/image_library.h>

#include <dlfcn.h>
#include <unistd.h>

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace rayrad::tonemap {

namespace {

/// The directory of the running program (/proc/self/exe), or "" when unknown.
std::filesystem::path programDirectory() {
    std::error_code error;
    const auto exe = std::filesystem::read_symlink("/proc/self/exe", error);
    return error ? std::filesystem::path() : exe.parent_path();
}

/// Where the module may be, in the order tried.
std::vector<std::string> candidates() {
    std::vector<std::string> out;
    if (const char* env = std::getenv("RAYRAD_IMAGE_MODULE"); env && *env) out.emplace_back(env);
    const auto dir = programDirectory();
    if (!dir.empty()) {
        out.push_back((dir / "librayrad_image.so").string());
#ifdef RAYRAD_IMAGE_MODULE_INSTALLED
        out.push_back((dir / RAYRAD_IMAGE_MODULE_INSTALLED / "librayrad_image.so").string());  // cmake --install
#endif
    }
#ifdef RAYRAD_IMAGE_MODULE_BUILD
    out.emplace_back(RAYRAD_IMAGE_MODULE_BUILD);  // tests and benches run from elsewhere in the build tree
#endif
    return out;
}

const ImageLibrary* load() {
    std::string errors;
    for (const std::string& path : candidates()) {
        if (!std::filesystem::exists(path)) continue;
        // RTLD_LOCAL: the module's libraries stay out of the program's symbol namespace.
        void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
        if (!handle) {
            errors += std::string("; ") + dlerror();
            continue;
        }
        using Entry = const ImageLibrary* (*)();
        auto entry = reinterpret_cast<Entry>(dlsym(handle, kImageLibraryEntry));
        if (!entry) {
            errors += "; " + path + " has no " + kImageLibraryEntry;
            continue;
        }
        return entry();  // never unloaded: objects it made may outlive any caller
    }
    throw std::runtime_error(
        "cannot load the image module librayrad_image.so (beside the rayrad program, or set "
        "RAYRAD_IMAGE_MODULE)" +
        errors);
}

}  // namespace

const ImageLibrary& imageLibrary() {
    static const ImageLibrary* library = load();
    return *library;
}

}  // namespace rayrad::tonemap
