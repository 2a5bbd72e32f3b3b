#include <radiosity/clusters/clusters.h>

#include <radiosity/mesh/contact_lines.h>  // kTouchingGap
#include <radiosity/mesh/covered_patches.h>
#include <radiosity/mesh/patch_reflectance.h>

#include <core/check.h>
#include <scene/polygon.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace rayrad::radiosity {

ClusterSamples powerSamples(const Cluster& c, const std::vector<double>& power) {
    double total = 0;
    for (double p : power) total += std::abs(p);
    if (!(total > 0)) return c.samples;
    // Stratified: sample k is the member where the running sum first passes (k + ½)/4 of it.
    ClusterSamples out{};
    double sum = 0;
    size_t m = 0;
    for (int k = 0; k < 4; ++k) {
        double target = (k + 0.5) / 4 * total;
        while (m + 1 < power.size() && sum + std::abs(power[m]) < target) sum += std::abs(power[m++]);
        out[k] = c.patches[m];
    }
    return out;
}

int Clustering::voxelDistance(const Cluster& a, const Cluster& b) const {
    return std::max(
        {std::abs(a.voxel[0] - b.voxel[0]), std::abs(a.voxel[1] - b.voxel[1]), std::abs(a.voxel[2] - b.voxel[2])});
}

VoxelRegions voxelRegions(const Clustering& clustering) {
    VoxelRegions out;
    std::map<std::array<int, 3>, uint32_t> index;
    for (const Cluster& C : clustering.clusters) {
        auto [at, added] = index.emplace(C.voxel, static_cast<uint32_t>(out.regions.size()));
        if (added) {
            const Vec3 corner = clustering.origin + Vec3(C.voxel[0], C.voxel[1], C.voxel[2]) * clustering.voxelSize;
            out.regions.push_back({corner + Vec3(0.5 * clustering.voxelSize), 0.0});
        }
        out.regionOf.push_back(at->second);
        VoxelRegions::Region& region = out.regions[at->second];
        region.radius = std::max(region.radius, glm::length(C.centroid - region.centre) + 0.5 * C.diameter);
    }
    return out;
}

size_t Clustering::multiPatchClusters() const {
    return static_cast<size_t>(
        std::count_if(clusters.begin(), clusters.end(), [](const Cluster& c) { return c.patches.size() > 1; }));
}

std::string Clustering::statistics() const {
    if (!enabled) return fmt::format("clusters: off ({} patches shoot on their own)", clusters.size());
    size_t multi = multiPatchClusters(), inMulti = 0, largest = 0;
    for (const auto& c : clusters) {
        if (c.patches.size() > 1) inMulti += c.patches.size();
        largest = std::max(largest, c.patches.size());
    }
    const std::string shrunk =
        derivedVoxelSize > voxelSize
            ? fmt::format(" (shrunk from {:.4g} m: clusters.max_voxel_crowding)", derivedVoxelSize)
            : "";
    return fmt::format(
        "clusters: {} of 2+ patches (mean {:.1f}, largest {}), {} patches in no cluster; voxel {:.4g} m{}, grid "
        "{}x{}x{}",
        multi, multi ? double(inMulti) / multi : 0.0, largest, clusters.size() - multi, voxelSize, shrunk, dims[0],
        dims[1], dims[2]);
}

namespace {
/// Voxels per axis of a grid of `edge` m over the scene's bounds (at least one; bounded,
/// so an absurd edge cannot overflow the cast before the caller rejects it).
std::array<int, 3> gridDims(const scene::Scene& scene, double edge) {
    const Vec3 extent = scene.boundsMax - scene.boundsMin;
    std::array<int, 3> dims;
    for (int a = 0; a < 3; ++a) dims[a] = static_cast<int>(std::clamp(std::ceil(extent[a] / edge - 1e-9), 1.0, 1e9));
    return dims;
}

/// The voxel holding p, clamped into the grid (a point on the bounds' far face lies in
/// the last voxel).
std::array<int, 3> voxelOf(const Vec3& p, const Vec3& origin, double edge, const std::array<int, 3>& dims) {
    std::array<int, 3> v;
    for (int a = 0; a < 3; ++a)
        v[a] = static_cast<int>(std::clamp(std::floor((p[a] - origin[a]) / edge), 0.0, double(dims[a] - 1)));
    return v;
}
}  // namespace

double voxelCrowding(const PatchMesh& mesh, const scene::Scene& scene, double edge) {
    if (mesh.patches.empty()) return 0;
    const std::array<int, 3> dims = gridDims(scene, edge);
    std::vector<std::array<int, 3>> cells;
    cells.reserve(mesh.patches.size());
    for (const Patch& p : mesh.patches) cells.push_back(voxelOf(p.centroid, scene.boundsMin, edge, dims));
    std::sort(cells.begin(), cells.end());
    double sum = 0;  // Σ_v n_v²
    for (size_t begin = 0, end = 0; begin < cells.size(); begin = end) {
        while (end < cells.size() && cells[end] == cells[begin]) ++end;
        sum += static_cast<double>(end - begin) * static_cast<double>(end - begin);
    }
    return sum / static_cast<double>(mesh.patches.size());
}

double derivedVoxelSize(const scene::Scene& scene, const PatchMesh& mesh, const scene::ClusterOptions& o) {
    if (o.patchesPerCluster > 0 && !mesh.patches.empty()) {
        // A planar cluster in a voxel of edge s covers about s²: s² = n · mean patch area.
        return std::sqrt(o.patchesPerCluster * mesh.totalArea() / mesh.patches.size());
    }
    double reference = o.referenceArea;
    if (reference <= 0)
        for (const auto& g : scene.groups) {
            double a = 0;
            for (const auto& poly : g.polygons) a += scene::polygonArea(g.positions, poly);
            reference = std::max(reference, a);
        }
    return std::sqrt(o.sizePercent / 100.0 * reference);
}

double clusterVoxelSize(const scene::Scene& scene, const PatchMesh& mesh, const scene::ClusterOptions& o) {
    if (o.voxelSize > 0) return o.voxelSize;
    double edge = derivedVoxelSize(scene, mesh, o);
    // Shrunk while crowded (see ClusterOptions::maxVoxelCrowding), at most 16 × in edge.
    constexpr int kMaxShrinks = 8;
    for (int k = 0;
         k < kMaxShrinks && o.maxVoxelCrowding > 0 && edge > 0 && voxelCrowding(mesh, scene, edge) > o.maxVoxelCrowding;
         ++k)
        edge /= std::sqrt(2.0);
    return edge;
}

namespace {

/// Members are tested for mutual visibility this far (× scene diagonal) off their surfaces.
constexpr double kMemberLift = 2e-5;

void finishCluster(const PatchMesh& mesh, const scene::Scene& scene, Cluster& c) {
    c.area = 0;
    c.centroid = Vec3(0.0);
    Vec3 n(0.0);
    c.meanReflectance = Rgb(0.0);
    for (uint32_t i : c.patches) {
        const Patch& p = mesh.patches[i];
        c.area += p.area;
        c.centroid += p.area * p.centroid;
        n += p.area * p.normal;
        c.meanReflectance += p.area * patchReflectance(scene, mesh, i);
    }
    c.centroid /= c.area;
    c.meanReflectance /= c.area;
    c.normal = glm::length(n) > 0 ? glm::normalize(n) : mesh.patches[c.patches[0]].normal;
    c.projectedArea = glm::length(n);
    double r = 0;
    c.planar = true;
    for (uint32_t i : c.patches) {
        const Patch& p = mesh.patches[i];
        for (int k = 0; k < 3; ++k) {
            r = std::max(r, glm::length(mesh.corner(p, k) - c.centroid));
            c.planar &= std::abs(glm::dot(mesh.corner(p, k) - c.centroid, c.normal)) < 1e-9 * (1 + p.diameter);
        }
        c.planar &= glm::dot(p.normal, c.normal) > 1 - 1e-12;
    }
    c.diameter = 2 * r;
    // Visibility samples: the member nearest the centroid, then members spread over the list.
    size_t n0 = c.patches.size();
    uint32_t nearest = c.patches[0];
    double best = 1e300;
    for (uint32_t i : c.patches) {
        double d = glm::length(mesh.patches[i].centroid - c.centroid);
        if (d < best) best = d, nearest = i;
    }
    c.samples = {nearest, c.patches[n0 / 4], c.patches[n0 / 2], c.patches[(3 * n0) / 4]};
}

}  // namespace

Clustering buildClusters(const scene::Scene& scene, const PatchMesh& mesh, const scene::ClusterOptions& o,
                         const Visibility* vis) {
    Clustering out;
    out.enabled = o.enabled;
    out.clusterOf.assign(mesh.patches.size(), 0);
    out.origin = scene.boundsMin;
    out.voxelSize = o.enabled ? clusterVoxelSize(scene, mesh, o) : std::max(scene.diagonal(), 1e-300);
    if (o.enabled && o.voxelSize <= 0) out.derivedVoxelSize = derivedVoxelSize(scene, mesh, o);
    CHECK(out.voxelSize > 0);
    out.dims = gridDims(scene, out.voxelSize);
    auto voxelOf = [&](const Vec3& p) { return radiosity::voxelOf(p, out.origin, out.voxelSize, out.dims); };

    if (!o.enabled) {
        out.clusters.resize(mesh.patches.size());
        for (uint32_t i = 0; i < mesh.patches.size(); ++i) {
            out.clusters[i].patches = {i};
            out.clusters[i].voxel = voxelOf(mesh.patches[i].centroid);
            out.clusterOf[i] = i;
            finishCluster(mesh, scene, out.clusters[i]);
        }
        return out;
    }

    const double cosTolerance = std::cos(glm::radians(o.normalToleranceDeg));
    const double lift = kMemberLift * scene.diagonal();  // m, off the surface
    auto seeEachOther = [&](const Patch& a, const Patch& b) {
        if (!vis) return true;
        // A segment between two points of a curved surface dips below it by about
        // d·sinθ/8 (θ the angle between the normals): lift by twice that.
        double h = lift + 0.25 * glm::length(a.centroid - b.centroid) * glm::length(glm::cross(a.normal, b.normal));
        return vis->visible(a.centroid + h * a.normal, b.centroid + h * b.normal);
    };
    // A patch under a cover (a surface in front of it nearer than a quarter of its size: the
    // ceiling above a troffer hung 1 cm below it, the floor under a low shelf) sees little
    // of what the open surface around it sees, yet the lifted segment through the gap
    // joined them: then a cluster sample under the cover darkened the whole cluster's
    // cluster→cluster light (blotches of the cluster's size on the hall's ceiling).
    // Covered and open patches are never one cluster.
    const std::vector<char> covered = !mesh.covered.empty() ? mesh.covered
                                      : vis                 ? coveredPatches(mesh, *vis, kCoverLift * scene.diagonal())
                                                            : std::vector<char>(mesh.patches.size(), 0);
    std::map<std::array<int, 3>, std::vector<uint32_t>> voxelClusters;  // voxel → cluster ids
    for (uint32_t i = 0; i < mesh.patches.size(); ++i) {
        const Patch& p = mesh.patches[i];
        auto v = voxelOf(p.centroid);
        auto& ids = voxelClusters[v];
        uint32_t chosen = UINT32_MAX;
        for (uint32_t id : ids)
            if (const uint32_t f = out.clusters[id].patches[0];
                covered[f] == covered[i] && glm::dot(mesh.patches[f].normal, p.normal) >= cosTolerance &&
                seeEachOther(mesh.patches[f], p)) {
                chosen = id;
                break;
            }
        if (chosen == UINT32_MAX) {
            chosen = static_cast<uint32_t>(out.clusters.size());
            out.clusters.emplace_back();
            out.clusters.back().voxel = v;
            ids.push_back(chosen);
        }
        out.clusters[chosen].patches.push_back(i);
        out.clusterOf[i] = chosen;
    }
    for (auto& c : out.clusters) finishCluster(mesh, scene, c);
    return out;
}

std::vector<std::vector<uint32_t>> touchingClusters(const PatchMesh& mesh, const Clustering& clustering,
                                                    const Visibility& spatial, double tolerance) {
    std::vector<std::vector<uint32_t>> touching(clustering.clusters.size());
    // Each mesh vertex once, with a cluster of a patch that uses it (a vertex shared by
    // patches of several clusters lies on each of them: those pairs are found from it).
    std::vector<std::vector<uint32_t>> clustersAt(mesh.vertices.size());
    for (size_t i = 0; i < mesh.patches.size(); ++i)
        for (uint32_t v : mesh.patches[i].v) {
            std::vector<uint32_t>& at = clustersAt[v];
            const uint32_t c = clustering.clusterOf[i];
            if (std::find(at.begin(), at.end(), c) == at.end()) at.push_back(c);
        }
    // The smallest patch at each vertex: the scale at which a gap beside it still counts as touching.
    std::vector<double> sizeAt(mesh.vertices.size(), std::numeric_limits<double>::infinity());
    for (const Patch& p : mesh.patches)
        for (uint32_t v : p.v) sizeAt[v] = std::min(sizeAt[v], p.diameter);
    std::vector<std::pair<uint32_t, uint32_t>> pairs;
    std::vector<Vec3> corners(3);
    for (size_t v = 0; v < mesh.vertices.size(); ++v) {
        if (clustersAt[v].empty()) continue;
        const Vec3& x = mesh.vertices[v];
        std::vector<uint32_t> near(clustersAt[v]), across;
        auto visit = [&](uint32_t j) {
            const uint32_t d = clustering.clusterOf[j];
            if (std::find(near.begin(), near.end(), d) != near.end()) return;
            const Patch& p = mesh.patches[j];
            for (int k = 0; k < 3; ++k) corners[k] = mesh.corner(p, k);
            const double distance = scene::segmentPolygonDistance(x, x, corners, p.normal);
            if (distance <= tolerance) {
                near.push_back(d);
            } else if (distance <= kTouchingGap * std::min(sizeAt[v], p.diameter) &&
                       glm::dot(x - corners[0], p.normal) > 0 &&
                       std::find(across.begin(), across.end(), d) == across.end()) {
                across.push_back(d);  // in front of the patch: the two faces of a partition touch nothing
            }
        };
        forPatchesNear(mesh, &spatial, x, std::max(tolerance, kTouchingGap * sizeAt[v]), visit);
        // Clusters meeting at x all touch one another; one across a gap touches x's own.
        for (uint32_t a : near)
            for (uint32_t b : near)
                if (a != b) pairs.emplace_back(a, b);
        for (uint32_t a : clustersAt[v])
            for (uint32_t b : across)
                if (std::find(near.begin(), near.end(), b) == near.end())
                    pairs.emplace_back(a, b), pairs.emplace_back(b, a);
    }
    std::sort(pairs.begin(), pairs.end());
    pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
    for (const auto& [a, b] : pairs) touching[a].push_back(b);
    return touching;
}

}  // namespace rayrad::radiosity
