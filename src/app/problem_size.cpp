#include <app/problem_size.h>

#include <core/input_error.h>
#include <radiosity/radiosity.h>

#include <fmt/format.h>

#include <cmath>

namespace rayrad::app {

namespace {
/// CPU seconds a sensor's final gather takes at least: the far clusters are taken in
/// groups, so it hardly grows with the mesh. Measured on 2 cores: 0.7–1.3 ms a
/// sensor on the cube (a 64 × 64 grid at 1 200 to 307 200 patches), 1.0 ms in the bench
/// hall (512 sensors); near furniture and mirrors more, and with a long tail: random
/// points on the living room's surfaces 18 ms median, 1.5 s at the 90th percentile (the
/// re-gathers around small near patches).
constexpr double kGatherSecondsPerSensor = 1e-3;
/// Peak memory model, measured: the process with its libraries and Embree (a solve of the
/// small cube peaks at 17 MiB), the image libraries when an image is read or written
/// (the image module: 125 MiB more), and bytes per patch at 1.2 M patches (bench/scale.sh:
/// 382–416 over runs; 400 errs high).
constexpr double kBaseBytes = 20.0 * (1 << 20);
constexpr double kImageLibraryBytes = 125.0 * (1 << 20);
constexpr double kBytesPerPatch = 400;
/// Voxels per side the cluster grid can index.
constexpr double kMaxVoxelsPerSide = 1e9;

/// The setting the cluster voxel comes from (see clusterVoxelSize()).
std::string voxelSetting(const scene::ClusterOptions& o) {
    return o.voxelSize > 0           ? "/clusters/voxel_size"
           : o.patchesPerCluster > 0 ? "/clusters/patches_per_cluster"
                                     : "/clusters/size_percent";
}
}  // namespace

double checkPatchCount(const std::string& file, const scene::Scene& scene) {
    const auto [estimate, edge] = radiosity::estimateMesh(scene);
    if (estimate <= scene.meshing.maxPatches) return estimate;
    throw InputError(placeMessage(
        file, scene.meshing.trianglesPerSurface > 0 ? "/radiosity/triangles_per_surface" : "/radiosity/max_edge",
        fmt::format("premeshing to {:.3g} m edges would make about {:.3g} patches (~{:.3g} GiB), more than "
                    "radiosity.max_patches ({:.3g}); use a larger max_edge, or raise max_patches if you mean it",
                    edge, estimate, estimate * 1024 / (1 << 30), scene.meshing.maxPatches)));
}

double estimatePeakBytes(size_t patches, size_t clusters, size_t mirrorImages, bool images) {
    // An image mirrors patches as they are used; it keeps two flags per cluster (which
    // clusters can send and receive through its chain).
    const double perImage = 2.0 * static_cast<double>(clusters);
    return kBaseBytes + (images ? kImageLibraryBytes : 0.0) + kBytesPerPatch * static_cast<double>(patches) +
           perImage * static_cast<double>(mirrorImages);
}

std::vector<std::string> costWarnings(const std::string& file, const scene::Scene& scene,
                                      const radiosity::PatchMesh& mesh, bool gatherSensors) {
    std::vector<std::string> out;
    const size_t patches = mesh.patches.size();
    if (patches == 0) return out;
    if (scene.clusters.enabled) {
        const double voxel = radiosity::clusterVoxelSize(scene, mesh, scene.clusters);
        const double side =
            std::max(scene.boundsMax.x - scene.boundsMin.x,
                     std::max(scene.boundsMax.y - scene.boundsMin.y, scene.boundsMax.z - scene.boundsMin.z));
        if (!(voxel > 0) || side / voxel > kMaxVoxelsPerSide)
            throw InputError(placeMessage(file, voxelSetting(scene.clusters),
                                          fmt::format("a cluster voxel of {:.3g} m makes {:.3g} voxels along the "
                                                      "scene's {:.3g} m; the grid allows {:.0e}",
                                                      voxel, side / voxel, side, kMaxVoxelsPerSide)));
        // Mean patch edge from the mean area of a right isosceles triangle, A = e²/2.
        const double meanEdge = std::sqrt(2 * mesh.totalArea() / patches);
        if (voxel < 0.5 * meanEdge)
            out.push_back(fmt::format(
                "{}: a cluster voxel of {:.3g} m is smaller than the patches (mean edge {:.3g} m): nearly every "
                "patch is a cluster of its own, so each shot visits all {} patches one by one and the secondary "
                "pass costs about as much as with clusters off",
                voxelSetting(scene.clusters), voxel, meanEdge, patches));
    }
    if (gatherSensors && !scene.sensors.empty() && scene.hasReflectance()) {
        const double seconds = kGatherSecondsPerSensor * static_cast<double>(scene.sensors.size());
        if (seconds > 600)
            out.push_back(
                fmt::format("/sensors: {} sensors: the final gather will take at least {:.0f} CPU-minutes "
                            "(about 1 ms a sensor in an open room, up to seconds among furniture and "
                            "mirrors: the sensor stage warns again with its measured cost)",
                            scene.sensors.size(), seconds / 60));
    }
    return out;
}

}  // namespace rayrad::app
