#include <radiosity/solution/solution.h>

#include <radiosity/mesh/contact_outlines.h>

#include <algorithm>

namespace rayrad::radiosity {

Rgb weightedVertexIndirect(const PatchMesh& mesh, const RadiositySolution& solution, size_t patch,
                           const std::array<double, 3>& w) {
    const Patch& p = mesh.patches[patch];
    return w[0] * solution.vertexIndirect[p.v[0]] + w[1] * solution.vertexIndirect[p.v[1]] +
           w[2] * solution.vertexIndirect[p.v[2]];
}

Rgb interpolateIndirect(const PatchMesh& mesh, const RadiositySolution& solution, size_t patch, double u, double v) {
    // Inside a patch that a contact outline crosses, only the corners on the point's side.
    const Rgb linear = weightedVertexIndirect(mesh, solution, patch, sameSideWeights(mesh, patch, u, v));
    if (solution.seamProfiles.empty()) return linear;
    return glm::max(linear + solution.seamProfiles.deltaAt(patch, u, v), Rgb(0.0));
}

}  // namespace rayrad::radiosity
