#include <radiosity/solution.h>

namespace rayrad::radiosity {

Rgb RadiositySolution::reflectedLuminance(const scene::Scene& scene, const PatchMesh& mesh, size_t i) const {
    const Rgb& rho = scene.materials[mesh.patches[i].material].reflectance;
    return rho * (directMean[i] + indirect[i]) / kPi;  // L = ρ E / π
}

void reconstructVertices(const PatchMesh& mesh, RadiositySolution& solution) {
    std::vector<Rgb> sum(mesh.vertices.size(), Rgb(0.0));
    std::vector<int> count(mesh.vertices.size(), 0);
    for (size_t i = 0; i < mesh.patches.size(); ++i)
        for (uint32_t v : mesh.patches[i].v) {
            sum[v] += solution.indirect[i];
            ++count[v];
        }
    solution.vertexIndirect.assign(mesh.vertices.size(), Rgb(0.0));
    for (size_t v = 0; v < sum.size(); ++v)
        if (count[v] > 0) solution.vertexIndirect[v] = sum[v] / static_cast<double>(count[v]);
}

Rgb interpolateIndirect(const PatchMesh& mesh, const RadiositySolution& solution, size_t patch, double u, double v) {
    const Patch& p = mesh.patches[patch];
    return (1 - u - v) * solution.vertexIndirect[p.v[0]] + u * solution.vertexIndirect[p.v[1]] +
           v * solution.vertexIndirect[p.v[2]];
}

}  // namespace rayrad::radiosity
