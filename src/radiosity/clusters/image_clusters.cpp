#include <radiosity/clusters/image_clusters.h>

#include <algorithm>
#include <cmath>

namespace rayrad::radiosity {

ImageCluster imageCluster(const PatchMesh& mesh, const Clustering& clustering, size_t c, const MirrorImage& image) {
    const Cluster& real = clustering.clusters[c];
    ImageCluster out;
    out.cluster = real;
    out.mesh.vertices.reserve(3 * real.patches.size());
    out.mesh.patches.reserve(real.patches.size());
    for (size_t k = 0; k < real.patches.size(); ++k) {
        ImagePatch p = imagePatch(mesh, mesh.patches[real.patches[k]], image);
        const uint32_t first = static_cast<uint32_t>(out.mesh.vertices.size());
        out.mesh.vertices.insert(out.mesh.vertices.end(), p.corners.begin(), p.corners.end());
        p.patch.v = {first, first + 1, first + 2};
        out.mesh.patches.push_back(p.patch);
        out.cluster.patches[k] = static_cast<uint32_t>(k);
    }
    Cluster& C = out.cluster;
    C.centroid = image.point(real.centroid);
    C.normal = image.direction(real.normal);
    for (int a = 0; a < 3 && clustering.voxelSize > 0; ++a)
        C.voxel[a] = static_cast<int>(std::floor((C.centroid[a] - clustering.origin[a]) / clustering.voxelSize));
    C.samples = out.local(real, real.samples);
    return out;
}

ClusterSamples ImageCluster::local(const Cluster& real, const ClusterSamples& samples) const {
    ClusterSamples out{};
    for (size_t m = 0; m < samples.size(); ++m)
        out[m] = static_cast<uint32_t>(std::find(real.patches.begin(), real.patches.end(), samples[m]) -
                                       real.patches.begin());
    return out;
}

std::vector<char> clustersFacing(const scene::Mirror& mirror, const PatchMesh& mesh, const Clustering& clustering) {
    std::vector<char> facing;
    facing.reserve(clustering.clusters.size());
    for (const Cluster& C : clustering.clusters)
        facing.push_back(std::any_of(C.patches.begin(), C.patches.end(), [&](uint32_t i) {
            return mirror.facedBy(mesh.patches[i].centroid, mesh.patches[i].normal);
        }));
    return facing;
}

}  // namespace rayrad::radiosity
