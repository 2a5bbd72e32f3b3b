#include <radiosity/member_groups.h>

#include <algorithm>

namespace rayrad::radiosity {

namespace {

void split(const PatchMesh& mesh, const Cluster& C, std::vector<uint32_t> members, size_t maxSize,
           std::vector<MemberGroup>& out) {
    if (members.size() <= maxSize) {
        MemberGroup g;
        double area = 0;
        for (uint32_t k : members) {
            const Patch& p = mesh.patches[C.patches[k]];
            g.centroid += p.area * p.centroid;
            area += p.area;
        }
        g.centroid = area > 0 ? g.centroid / area : mesh.patches[C.patches[members[0]]].centroid;
        double r = 0;
        for (uint32_t k : members)
            for (int corner = 0; corner < 3; ++corner)
                r = std::max(r, glm::length(mesh.corner(mesh.patches[C.patches[k]], corner) - g.centroid));
        g.diameter = 2 * r;
        g.members = std::move(members);
        out.push_back(std::move(g));
        return;
    }
    Vec3 lo(1e300), hi(-1e300);
    for (uint32_t k : members) {
        lo = glm::min(lo, mesh.patches[C.patches[k]].centroid);
        hi = glm::max(hi, mesh.patches[C.patches[k]].centroid);
    }
    const Vec3 extent = hi - lo;
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
    const auto middle = members.begin() + static_cast<std::ptrdiff_t>(members.size() / 2);
    std::nth_element(members.begin(), middle, members.end(), [&](uint32_t a, uint32_t b) {
        return mesh.patches[C.patches[a]].centroid[axis] < mesh.patches[C.patches[b]].centroid[axis];
    });
    split(mesh, C, std::vector<uint32_t>(members.begin(), middle), maxSize, out);
    split(mesh, C, std::vector<uint32_t>(middle, members.end()), maxSize, out);
}

}  // namespace

std::vector<std::vector<MemberGroup>> memberGroups(const PatchMesh& mesh, const Clustering& clustering, size_t maxSize) {
    std::vector<std::vector<MemberGroup>> out(clustering.clusters.size());
    for (size_t c = 0; c < clustering.clusters.size(); ++c) {
        const Cluster& C = clustering.clusters[c];
        std::vector<uint32_t> members(C.patches.size());
        for (uint32_t k = 0; k < members.size(); ++k) members[k] = k;
        split(mesh, C, std::move(members), std::max<size_t>(1, maxSize), out[c]);
    }
    return out;
}

}  // namespace rayrad::radiosity
