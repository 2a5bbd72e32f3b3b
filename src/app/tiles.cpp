#include <app/tiles.h>

#include <app/image_output.h>
#include <app/result_checks.h>
#include <core/input_error.h>
#include <core/input_file.h>
#include <core/hash.h>
#include <core/output_file.h>
#include <radiosity/radiosity.h>
#include <tonemap/image_io.h>

#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <map>

namespace rayrad::app {

namespace {

std::string attribute(const std::vector<std::pair<std::string, std::string>>& attributes, const std::string& name,
                      const std::string& path) {
    for (const auto& [n, v] : attributes)
        if (n == name) return v;
    throw InputError(placeMessage(path, "", "not a tile of a rayrad rendering (no " + name + "; render --tile writes tiles)"));
}

}  // namespace

std::string renderFingerprint(const PipelineRun& run) {
    const radiosity::SolutionFingerprint f = radiosity::fingerprintOf(run.scene, run.mesh);
    Hash h;
    h << f.geometry << f.materials << f.lights << f.settings;
    if (run.scene.camera) {
        const scene::Camera& c = *run.scene.camera;
        h << c.position << c.lookAt << c.up << c.verticalFovDeg << c.width << c.height << static_cast<int>(c.projection)
          << c.orthoHeight;
    }
    const scene::RenderOptions& r = run.scene.render;
    h << r.samplesPerPixel << r.seed << r.areaLightSamples << r.directThreshold << r.shareFarShadows << r.maxDepth
      << r.displayRangeCompression << r.smoothingAngleDeg << r.gatherIndirect;
    return fmt::format("{:016x}", h.value());
}

Tile parseTile(const std::string& text) {
    Tile t;
    char end = 0;
    if (std::sscanf(text.c_str(), "%d/%d%c", &t.index, &t.count, &end) != 2 || t.count < 1 || t.count > 100000 || t.index < 1 ||
        t.index > t.count)
        throw InputError(placeMessage("", "--tile", "expected I/N with 1 ≤ I ≤ N (the I-th of N bands), got \"" + text + "\""));
    return t;
}

std::pair<int, int> tileRows(const Tile& t, int height) {
    if (t.count == 0) return {0, height};
    const auto h = static_cast<long long>(height);
    return {static_cast<int>((t.index - 1) * h / t.count), static_cast<int>(t.index * h / t.count)};
}

std::string encodeTile(const std::string& path, const HdrImage& image, const Tile& t, const std::string& description,
                       const std::string& fingerprint) {
    const auto [first, last] = tileRows(t, image.height);
    HdrImage band(image.width, last - first);
    for (int y = first; y < last; ++y)
        for (int x = 0; x < image.width; ++x) band.at(x, y - first) = image.at(x, y);
    return tonemap::encodeExr(path, band, fmt::format("tile {}/{} of: {}", t.index, t.count, description),
                              {{"rayrad:tile", fmt::format("{}/{}", t.index, t.count)},
                               {"rayrad:image_size", fmt::format("{}x{}", image.width, image.height)},
                               {"rayrad:description", description},
                               {"rayrad:fingerprint", fingerprint}});
}

int mergeTiles(const std::vector<std::string>& outputs, const std::vector<std::string>& tiles) {
    OutputFiles files;
    for (const auto& t : tiles) files.addInput(t);
    addImageOutputs(outputs, files);
    HdrImage full;
    std::string description, fingerprint;
    int count = 0;
    std::map<int, std::string> seen;  // index → tile file
    for (const auto& path : tiles) {
        checkInputFile(path, "tile");
        std::vector<std::pair<std::string, std::string>> attributes;
        const HdrImage band = tonemap::readImage(path, &attributes);
        const Tile t = parseTile(attribute(attributes, "rayrad:tile", path));
        int width = 0, height = 0;
        char end = 0;
        const std::string size = attribute(attributes, "rayrad:image_size", path);
        // The caps of a camera's resolution: a forged size is bad input, not an allocation.
        if (std::sscanf(size.c_str(), "%dx%d%c", &width, &height, &end) != 2 || width < 1 || height < 1 ||
            width > 16384 || height > 16384 || static_cast<long long>(width) * height > 100'000'000LL)
            throw InputError(placeMessage(path, "", "a damaged tile (image size \"" + size +
                                                        "\"; an image is at most 16384 pixels a side and 10⁸ in all)"));
        const std::string d = attribute(attributes, "rayrad:description", path);
        const std::string print = attribute(attributes, "rayrad:fingerprint", path);
        if (seen.empty()) {
            full = HdrImage(width, height);
            description = d;
            fingerprint = print;
            count = t.count;
        } else if (width != full.width || height != full.height || t.count != count || d != description) {
            throw InputError(placeMessage(path, "", fmt::format("is a tile of another rendering than {} (size, tile count or "
                                                                "scene differ)", seen.begin()->second)));
        } else if (print != fingerprint) {
            throw InputError(placeMessage(path, "", fmt::format("is a tile of another rendering than {}: the scene's "
                                                                "geometry, materials, lights, settings or camera "
                                                                "differ (render fingerprint {} against {})",
                                                                seen.begin()->second, print, fingerprint)));
        }
        if (!seen.emplace(t.index, path).second)
            throw InputError(placeMessage(path, "", fmt::format("tile {}/{} is given twice (also {})", t.index, t.count, seen[t.index])));
        const auto [first, last] = tileRows(t, height);
        if (band.width != width || band.height != last - first)
            throw InputError(placeMessage(path, "", fmt::format("a damaged tile: {}×{} where tile {}/{} of {}×{} has {}×{}",
                                                                band.width, band.height, t.index, t.count, width, height,
                                                                width, last - first)));
        for (int y = first; y < last; ++y)
            for (int x = 0; x < width; ++x) full.at(x, y) = band.at(x, y - first);
    }
    if (static_cast<int>(seen.size()) != count) {
        std::string missing;
        for (int i = 1; i <= count; ++i)
            if (!seen.count(i)) missing += (missing.empty() ? "" : ", ") + std::to_string(i);
        throw InputError(placeMessage("", "merge", fmt::format("missing tile(s) {} of {}", missing, count)));
    }
    checkRenderedImage(full, false);
    tonemap::DisplayOptions display;
    stageImages(outputs, full, full, display, description, files);  // as render stages them
    files.commit();
    for (const auto& p : outputs) fmt::print(stderr, "wrote {}\n", p);
    return 0;
}

}  // namespace rayrad::app
