#include <scene/file_views.h>

#include <core/input_error.h>
#include <scene/mesh_import.h>

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>

namespace rayrad::scene {

namespace {

constexpr int kFileViewRows = 480;

bool isGltf(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    return ext == ".gltf" || ext == ".glb";
}

/// The file's camera in the scene: the object's transform on its place and axes.
CameraDesc placedCamera(const ImportedCamera& c, const ObjectDesc& o) {
    CameraDesc d;
    d.where = o.where + "/file (camera \"" + c.name + "\")";
    const glm::dmat3 linear(o.transform);
    d.position = Vec3(o.transform * glm::dvec4(c.position, 1.0));
    const Vec3 up = linear * c.up;
    d.lookAt = d.position + glm::normalize(linear * c.direction);
    d.up = glm::normalize(up);
    d.height = kFileViewRows;
    d.width = c.aspectRatio > 0 ? std::clamp(static_cast<int>(std::lround(kFileViewRows * c.aspectRatio)), 16, 8192)
                                : kFileViewRows * 4 / 3;
    if (c.orthographic) {
        d.projection = Projection::Orthographic;
        d.orthoHeight = 2 * c.ymag * glm::length(up);
    } else {
        d.verticalFovDeg = c.yfovDeg;
    }
    return d;
}

}  // namespace

void addFileViews(SceneDesc& desc) {
    for (const ObjectDesc& o : desc.objects) {
        if (o.kind != ObjectKind::Mesh || !isGltf(o.resolvedFile)) continue;
        for (const ImportedCamera& c : importMesh(o.resolvedFile, desc.file, o.where).cameras) {
            const bool taken = std::any_of(desc.views.begin(), desc.views.end(),
                                           [&](const auto& v) { return v.first == c.name; });
            if (taken || c.name == "all")
                throw InputError(placeMessage(desc.file, o.where + "/file",
                                              fmt::format("the file's camera \"{}\" has the name of a view the scene "
                                                          "already has{}: rename one",
                                                          c.name, c.name == "all" ? " (\"all\" is reserved)" : "")));
            const CameraDesc d = placedCamera(c, o);
            if (!desc.camera) desc.camera = d;
            desc.views.emplace_back(c.name, d);
        }
    }
}

}  // namespace rayrad::scene
