#include <app/scene_info.h>

#include <app/glare/ugr_table.h>
#include <app/photometry_report.h>
#include <core/input_error.h>
#include <core/output_file.h>
#include <app/pipeline.h>
#include <app/problem_size.h>
#include <app/scene_warnings.h>
#include <radiosity/radiosity.h>
#include <raytrace/embree_scene.h>
#include <scene/photometry.h>

#include <fmt/format.h>

#include <cmath>
#include <cstdio>

namespace rayrad::app {

namespace {

/// What a material is, for the listing: its kind and the values that matter for it.
std::string materialText(const scene::Material& m) {
    switch (m.kind) {
        case scene::SurfaceKind::Diffuse: return "diffuse, reflectance " + toString(m.reflectance);
        case scene::SurfaceKind::Mirror: return "mirror, Ks " + toString(m.specular);
        case scene::SurfaceKind::Glass: return fmt::format("glass, index {:g}", m.ior);
        case scene::SurfaceKind::Opening: return fmt::format("opening, transmittance {:g}", m.transmittance);
    }
    return "?";
}

/// info FILE.ies|FILE.ldt: its photometry and, asked, its UGR table.
int printPhotometryInfo(const InfoArgs& args) {
    const std::string& file = args.common.scene;
    OutputFiles files;
    files.addInput(file);
    if (!args.ugrCsv.empty()) files.add(args.ugrCsv);
    const scene::Photometry p = scene::readPhotometry(file);
    fmt::print("{}", app::photometryReport(p));
    if (!args.ugrTable && args.ugrCsv.empty()) return 0;
    const UgrTable table = ugrTable(p, args.ugrSpacing);
    fmt::print("\n{}", ugrTableText(table, p));
    if (!args.ugrCsv.empty()) {
        files.set(args.ugrCsv, ugrTableCsv(table));
        files.commit();
        fmt::print(stderr, "wrote {}\n", args.ugrCsv);
    }
    return 0;
}

}  // namespace

int printSceneInfo(const InfoArgs& args, const std::vector<scene::Override>& overrides) {
    const std::string& file = args.common.scene;
    if (scene::isPhotometricFile(file)) return printPhotometryInfo(args);
    if (args.ugrTable || !args.ugrCsv.empty())
        throw InputError(placeMessage("", "--ugr-table", "a UGR table is made for a photometric file (.ies, .ldt), not a "
                                                          "scene: use observers in the scene for UGR in a room"));
    auto scene = app::loadSceneFile(file, overrides);
    const double estimate = app::checkPatchCount(file, scene);
    auto mesh = radiosity::prepareMesh(scene, {});
    size_t emissive = 0;
    for (const auto& g : scene.groups)
        if (scene.materials[g.material].isEmissive()) emissive += g.polygons.size();
    fmt::print("scene: {}\n", file);
    fmt::print("materials: {}\n", scene.materials.size());
    for (const auto& m : scene.materials)
        fmt::print("  {}: {}{}\n", m.name, materialText(m),
                   m.isEmissive() ? fmt::format(", emits {} cd/m²", toString(m.emission)) : "");
    fmt::print("surface groups: {}, input polygons: {}\n", scene.groups.size(), scene.polygonCount());
    fmt::print(
        "patches (premeshed triangles): {} (estimated {:.0f}; target edge {:.4g} m), vertices: {}, area: {:.6g} m²\n",
        mesh.patches.size(), estimate, mesh.edgeLength, mesh.vertices.size(), mesh.totalArea());
    auto embree = raytrace::buildEmbreeScene(scene, mesh);
    const radiosity::Clustering clustering = radiosity::buildClusters(scene, mesh, scene.clusters, embree.get());
    fmt::print("{}\n", clustering.statistics());
    for (const auto& w : app::costWarnings(file, scene, mesh, true)) fmt::print("warning: {}\n", w);
    std::fflush(stdout);  // before the per-sensor checks, which take a while for very many sensors
    for (const auto& w : app::sceneWarnings(scene, mesh, *embree)) fmt::print("warning: {}\n", w);
    fmt::print("point/spot lights and luminaires: {}, area-light polygons: {}\n", scene.lights.size(), emissive);
    for (const auto& l : scene.lights) {
        if (l.photometry) {
            const auto peak = l.photometry->peak();
            fmt::print("  luminaire {} at {}: {:.1f} lm ({:.4g} × the file's table), peak {:.1f} cd, nadir {}, C0 {}\n",
                       l.photometry->file, toString(l.position), l.photometricFlux, l.photometricScale,
                       peak.candela * l.photometricScale, toString(l.nadir), toString(l.c0));
            continue;
        }
        fmt::print("  {} at {}: {} cd{}\n", l.isSpot ? "spot" : "point", toString(l.position), toString(l.intensity),
                   l.isSpot ? fmt::format(", axis {}, cones {:.4g}°/{:.4g}°", toString(l.direction),
                                          glm::degrees(std::acos(l.cosInner)), glm::degrees(std::acos(l.cosOuter)))
                            : "");
    }
    fmt::print("sensors: {}\n", scene.sensors.size());
    for (const auto& o : scene.observers)
        fmt::print("observer \"{}\" at {} looking {}{}\n", o.name, toString(o.position), toString(o.direction),
                   o.ugrLimit ? fmt::format(", UGR limit {:g}{}", *o.ugrLimit, o.task.empty() ? "" : " (" + o.task + ")")
                              : std::string());
    const radiosity::DirectLight lights(scene);  // its virtual lights are the mirror images' copies of the lights
    const size_t images = lights.imageCount();
    if (!scene.mirrors.empty())
        fmt::print("mirror images: {} ({}){}\n", images,
                   scene.mirrorImages.imageMethod() ? "chains of reflections" : "mirrors ignored",
                   images > 0 ? fmt::format(", {} virtual lights", lights.virtualLightCount()) : "");
    const auto peakMiB = [&](bool rendering) {
        return app::estimatePeakBytes(mesh.patches.size(), clustering.clusters.size(), images, rendering) / (1 << 20);
    };
    fmt::print("expected peak memory: about {:.0f} MiB to solve, {:.0f} MiB to render ({} patches, {} clusters{})\n",
               peakMiB(false), peakMiB(true), mesh.patches.size(), clustering.clusters.size(),
               images > 0 ? fmt::format(", {} mirror images", images) : "");
    for (const auto& v : scene.views) {
        const auto& c = v.camera;
        const std::string lens = c.projection == scene::Projection::Fisheye        ? "fisheye 180 deg"
                                 : c.projection == scene::Projection::Orthographic ? fmt::format("orthographic, {:g} m high", c.orthoHeight)
                                                                                   : fmt::format("vfov {:g} deg", c.verticalFovDeg);
        fmt::print("view \"{}\": {}x{}, {}{}\n", v.name, c.width, c.height, lens,
                   &v == &scene.views.front() ? " (the default)" : "");
    }
    fmt::print("bounds: {} to {} (diagonal {:.6g} m)\n", toString(scene.boundsMin), toString(scene.boundsMax),
               scene.diagonal());
    if (scene.warnings.degeneratePolygons > 0)
        fmt::print("warning: {} zero-area or duplicate triangles dropped\n", scene.warnings.degeneratePolygons);
    if (scene.warnings.droppedMeshFaces > 0)
        fmt::print("warning: {} mesh-file faces dropped (points, lines, or indices out of range)\n",
                   scene.warnings.droppedMeshFaces);
    if (scene.warnings.clampedFileReflectances > 0)
        fmt::print("warning: {} mesh-file materials had a reflectance above {} and were clamped to it\n",
                   scene.warnings.clampedFileReflectances, scene::kMaxFileReflectance);
    for (const auto& w : scene.warnings.fileWarnings) fmt::print("warning: {}\n", w);
    if (!scene.textures.empty()) fmt::print("textures: {}\n", scene.textures.size());
    fmt::print("stages needed: premesh, direct light{}{}{}{}\n", scene.hasReflectance() ? ", secondary pass" : "",
               scene.sensors.empty() ? "" : ", sensor gather",
               scene.observers.empty() ? "" : fmt::format(", glare ({} observers)", scene.observers.size()),
               scene.camera ? ", ray trace" : "");
    std::vector<std::string> skipped;
    if (!scene.hasReflectance()) skipped.push_back("secondary pass (no surface reflects light)");
    if (scene.sensors.empty()) skipped.push_back("sensor gather (no sensors)");
    if (!scene.camera) skipped.push_back("ray trace (no camera)");
    for (const auto& s : skipped) fmt::print("not needed: {}\n", s);
    return 0;
}

}  // namespace rayrad::app
