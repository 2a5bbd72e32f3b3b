#include <radiosity/display/contact_vertices.h>

#include <radiosity/mesh/contact_outlines.h>
#include <radiosity/mesh/mesh_location.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace rayrad::radiosity {

std::vector<GatherPoint> contactVertices(const PatchMesh& mesh, const std::vector<int64_t>& patchOf, double minDiameter,
                                         double nudge) {
    // The outlines crossing each patch at least minDiameter across.
    auto crossings = [&](size_t i) {
        const bool counts = !mesh.outlineBegin.empty() && mesh.patches[i].diameter >= minDiameter;
        const ContactOutline* first = counts ? mesh.outlines.data() + mesh.outlineBegin[i] : nullptr;
        return std::make_pair(first, counts ? first + (mesh.outlineBegin[i + 1] - mesh.outlineBegin[i]) : nullptr);
    };

    // An outline running through a corner splits the patches around it too, those it only
    // touches there: their other corners on its far side must not take the light of its
    // near side (the reconstruction averages both).
    auto touched = [&](size_t i) {
        if (mesh.patches[i].diameter < minDiameter) return false;
        for (uint32_t v : mesh.patches[i].v)
            if (auto [first, last] = mesh.outlinesThrough(v); first != last) return true;
        return false;
    };
    // Per vertex, the crossed or touched patches around it.
    std::vector<std::vector<uint32_t>> crossed(mesh.vertices.size());
    for (uint32_t i = 0; i < mesh.patches.size(); ++i)
        if (crossings(i).first != crossings(i).second || touched(i))
            for (uint32_t v : mesh.patches[i].v) crossed[v].push_back(i);
    std::vector<GatherPoint> points;
    for (size_t v = 0; v < mesh.vertices.size(); ++v) {
        if (crossed[v].empty() || patchOf[v] < 0) continue;
        const Vec3& x = mesh.vertices[v];
        const Patch& own = mesh.patches[patchOf[v]];
        if (!mesh.underSolid[v]) {
            // On an outline: `nudge` in front of the surfaces through it, in the plane (the
            // value serves the points in front: sameSideWeights). Elsewhere where it is.
            Vec3 front(0.0);
            for (auto [n, last] = mesh.outlinesThrough(static_cast<uint32_t>(v)); n != last; ++n)
                front += *n - glm::dot(*n, own.normal) * own.normal;
            const Vec3 at = glm::length(front) > 0 ? x + nudge * glm::normalize(front)
                                                   : nudgeInside(mesh, static_cast<size_t>(patchOf[v]), x, nudge);
            points.push_back({v, at, own.normal});
            continue;
        }
        // Under the box: from the nearest point of the outlines, `nudge` in front of the
        // crossing surface there, in the surface's plane (crossed[v] holds only patches at
        // least minDiameter across, whose outlines all count).
        const auto at = inFrontOfOutline(mesh, x, own.normal, crossed[v], nudge);
        if (!at) continue;  // under a solid, among touched patches only: left as it is
        points.push_back({v, *at, own.normal});
    }
    return points;
}

}  // namespace rayrad::radiosity
