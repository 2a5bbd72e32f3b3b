#include <app/lit_mesh_export.h>

#include <app/walkthrough.h>
#include <radiosity/radiosity.h>
#include <scene/gltf_writer.h>

#include <glm/gtc/quaternion.hpp>

#include <algorithm>

namespace rayrad::app {

namespace {

/// The scene's default view as a glTF camera: the node's frame has −Z along the viewing
/// direction and +Y along the (orthogonalised) up vector.
std::optional<scene::GlbCamera> glbCamera(const scene::Scene& s) {
    if (!s.camera || s.camera->projection != scene::Projection::Perspective) return std::nullopt;
    const scene::Camera& c = *s.camera;
    const Vec3 back = glm::normalize(c.position - c.lookAt);
    const Vec3 right = glm::normalize(glm::cross(c.up, back));
    const Vec3 up = glm::cross(back, right);
    const glm::dquat q = glm::quat_cast(glm::dmat3(right, up, back));
    scene::GlbCamera g;
    for (int k = 0; k < 3; ++k) g.position[k] = static_cast<float>(c.position[k]);
    g.rotation[0] = static_cast<float>(q.x), g.rotation[1] = static_cast<float>(q.y);
    g.rotation[2] = static_cast<float>(q.z), g.rotation[3] = static_cast<float>(q.w);
    g.verticalFovRad = glm::radians(c.verticalFovDeg);
    g.aspect = static_cast<double>(c.width) / c.height;
    return g;
}

}  // namespace

std::string exportLitMesh(const PipelineRun& run, const tonemap::DisplayOptions& display, double adaptation,
                          const std::string& sceneFile) {
    const auto& mesh = run.mesh;
    const auto& solution = run.lighting.solution;
    // E_direct at each vertex: the mean of its patches' corner values (vertices are shared
    // only within a surface group, which has one material).
    // ρ likewise: the mean of the patches' (a texture's mean where textured).
    std::vector<Rgb> direct(mesh.vertices.size(), Rgb(0.0)), rho(mesh.vertices.size(), Rgb(0.0));
    std::vector<int> patchesAround(mesh.vertices.size(), 0);
    std::vector<int> material(mesh.vertices.size(), -1);
    for (size_t i = 0; i < mesh.patches.size(); ++i)
        for (int k = 0; k < 3; ++k) {
            const uint32_t v = mesh.patches[i].v[k];
            direct[v] += Rgb(solution.directCorner[3 * i + k]);
            rho[v] += radiosity::patchReflectance(run.scene, mesh, i);
            ++patchesAround[v];
            material[v] = mesh.patches[i].material;
        }

    // Each used vertex once, in order; luminance L = L_e + ρ E / π (cd/m²).
    std::vector<uint32_t> outIndex(mesh.vertices.size(), 0);
    scene::ColouredMesh out;
    out.scalarName = "_LUMINANCE";
    HdrImage luminances;  // one "pixel" per vertex, for the display transform
    luminances.height = 1;
    for (size_t v = 0; v < mesh.vertices.size(); ++v) {
        if (patchesAround[v] == 0) continue;
        const scene::Material& m = run.scene.materials[static_cast<size_t>(material[v])];
        const Rgb indirect = solution.vertexIndirect.empty() ? Rgb(0.0) : solution.vertexIndirect[v];
        const double n = patchesAround[v];
        const Rgb L = m.emission + rho[v] / n * (direct[v] / n + indirect) / kPi;
        outIndex[v] = static_cast<uint32_t>(luminances.pixels.size());
        luminances.pixels.push_back(L);
        for (int k = 0; k < 3; ++k) out.positions.push_back(static_cast<float>(mesh.vertices[v][k]));
        out.scalar.push_back(static_cast<float>(luminance(L)));
    }
    luminances.width = static_cast<int>(luminances.pixels.size());
    for (const auto& p : mesh.patches)
        for (int k = 0; k < 3; ++k) out.indices.push_back(outIndex[p.v[k]]);

    const tonemap::DisplayOptions steady = steadyDisplay(adaptation, display);
    for (const Rgb& c : tonemap::toDisplayLinear(luminances, steady))
        for (int k = 0; k < 3; ++k) out.colours.push_back(static_cast<float>(std::clamp(c[k], 0.0, 1.0)));

    scene::GlbExtras extras;
    extras.text = {{"scene", sceneFile},
                   {"colours", "COLOR_0: linear display RGB of the luminance through " +
                                   tonemap::describeDisplay(luminances, steady)},
                   {"_LUMINANCE", "luminance Y of each vertex, cd/m² (absolute)"}};
    if (adaptation > 0) extras.numbers.push_back({"adaptation_luminance_cd_m2", adaptation});
    if (!steady.autoExposure) extras.numbers.push_back({"exposure_stops", steady.exposureStops});
    return scene::encodeColouredGlb(out, extras, "rayrad " RAYRAD_VERSION, glbCamera(run.scene));
}

}  // namespace rayrad::app
