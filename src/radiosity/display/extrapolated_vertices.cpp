#include <radiosity/display/extrapolated_vertices.h>

#include <radiosity/mesh/mesh_location.h>

#include <algorithm>
#include <limits>

namespace rayrad::radiosity {

std::vector<GatherPoint> extrapolatedVertices(const PatchMesh& mesh, const RadiositySolution& solution,
                                              const std::vector<int64_t>& patchOf, const std::vector<char>& taken,
                                              double minDiameter, double nudge) {
    const size_t nv = mesh.vertices.size();
    // Per vertex: Y of the open patches' values around it (min, max, sum, count) and of
    // the covered ones, which count only where no open patch is.
    struct Range {
        double lo = std::numeric_limits<double>::infinity(), hi = -std::numeric_limits<double>::infinity();
        double sum = 0;
        int count = 0;
        void add(double y) { lo = std::min(lo, y), hi = std::max(hi, y), sum += y, ++count; }
    };
    std::vector<Range> open(nv), covered(nv);
    for (size_t i = 0; i < mesh.patches.size(); ++i) {
        const double y = luminance(solution.indirect[i]);
        const bool isCovered = mesh.isCovered(i);
        for (uint32_t v : mesh.patches[i].v) (isCovered ? covered : open)[v].add(y);
    }
    const std::vector<double> angleSum = vertexAngleSums(mesh);
    std::vector<GatherPoint> out;
    for (size_t v = 0; v < nv; ++v) {
        if (isInnerVertex(angleSum[v])) continue;  // interpolated, not extrapolated
        if (taken[v] || patchOf[v] < 0 || mesh.patches[static_cast<size_t>(patchOf[v])].diameter < minDiameter)
            continue;
        const Range& r = open[v].count > 0 ? open[v] : covered[v];
        if (r.count == 0) continue;
        const double mean = r.sum / r.count, y = luminance(solution.vertexIndirect[v]);
        const double outside = std::max({r.lo - y, y - r.hi, 0.0});  // lx
        if (!(mean > 0) || outside <= kExtrapolationShare * mean) continue;
        const size_t p = static_cast<size_t>(patchOf[v]);
        out.push_back({v, nudgeInside(mesh, p, mesh.vertices[v], nudge), mesh.patches[p].normal});
    }
    return out;
}

}  // namespace rayrad::radiosity
