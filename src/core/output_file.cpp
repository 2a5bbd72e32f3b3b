#include <core/output_file.h>

#include <core/input_error.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <unistd.h>

namespace rayrad {

namespace fs = std::filesystem;

void checkWritable(const std::string& path) {
    fs::path p(path);
    fs::path dir = p.has_parent_path() ? p.parent_path() : fs::path(".");
    std::error_code ec;
    if (fs::is_directory(p, ec)) throw InputError(placeMessage(path, "", "is a directory, not an output file"));
    if (!fs::is_directory(dir, ec))
        throw InputError(placeMessage(path, "", "cannot write: directory '" + dir.string() + "' does not exist"));
    if (access(dir.c_str(), W_OK) != 0)
        throw InputError(placeMessage(path, "", "cannot write: directory '" + dir.string() + "' is not writable"));
    if (fs::exists(p, ec) && access(p.c_str(), W_OK) != 0)
        throw InputError(placeMessage(path, "", "cannot write: the file exists and is read-only"));
}

void writeAtomically(const std::string& path, const std::function<void(const std::string&)>& write) {
    fs::path p(path);
    fs::path tmp = p;
    // Keep the extension last: libraries pick the format from it.
    tmp.replace_filename("." + p.stem().string() + ".tmp" + std::to_string(getpid()) + p.extension().string());
    try {
        write(tmp.string());
    } catch (...) {
        std::remove(tmp.c_str());
        throw;
    }
    if (std::rename(tmp.c_str(), p.c_str()) != 0) {
        std::string why = std::strerror(errno);
        std::remove(tmp.c_str());
        throw InputError(placeMessage(path, "", "cannot write: " + why));
    }
}

}  // namespace rayrad
