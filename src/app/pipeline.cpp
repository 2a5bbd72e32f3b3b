#include <app/pipeline.h>

#include <app/result_checks.h>

#include <app/grid_statistics.h>
#include <app/image_output.h>
#include <app/problem_size.h>
#include <app/scene_warnings.h>
#include <core/input_error.h>
#include <core/input_file.h>
#include <core/progress.h>
#include <raytrace/camera.h>
#include <raytrace/ray_tracer.h>
#include <scene/light_groups.h>
#include <tonemap/texture_images.h>

#include <fmt/format.h>

#include <cmath>
#include <optional>

namespace rayrad::app {

namespace {
/// The scene built from its description, with its texture images opened.
scene::Scene buildSceneFrom(const scene::SceneDesc& desc) {
    scene::Scene scene = scene::buildScene(desc);
    if (!scene.textures.empty()) scene.textureImages = tonemap::openTextureImages(scene.textures);
    return scene;
}
}  // namespace

scene::Scene loadSceneFile(const std::string& file, const std::vector<scene::Override>& overrides) {
    return buildSceneFrom(scene::loadScene(file, overrides));
}

namespace {

/// Where the radiosity stage reports its sub-stages: the run's stage table and skip list.
radiosity::StageLog stageLog(PipelineRun& run, const PipelineOptions& options) {
    return {&run.report, &run.skipped, options.quiet, &run.warnings};
}

/// The shading normals, made before the first image (images only: the radiosity and the
/// sensors use the triangles' own normals).
void ensureShadingNormals(PipelineRun& run) {
    if (run.shadingNormals) return;
    radiosity::computeShadingNormals(run.mesh, run.scene.render.smoothingAngleDeg);
    run.shadingNormals = true;
}

/// L_c for the display average (render.display_range_compression), 0 when off.
double displayCompression(const scene::Scene& scene, const radiosity::PatchMesh& mesh,
                          const radiosity::RadiositySolution& solution) {
    return scene.render.displayRangeCompression ? raytrace::compressionLuminance(scene, mesh, solution) : 0.0;
}

std::optional<double> errorPct(double value, const std::optional<double>& ref) {
    if (!ref || *ref == 0) return std::nullopt;
    return 100.0 * (value - *ref) / *ref;
}

/// What is done at each push-pull: the convergence log and the snapshots. The solution
/// is copied so the solve itself is not disturbed; the time is not counted as solve time.
class PushPullObserver {
  public:
    PushPullObserver(PipelineRun& run, const PipelineOptions& options) : m_run(run), m_options(options) {
        // Where each referenced sensor lies on the mesh does not change during the solve.
        for (const auto& s : run.scene.sensors)
            if (s.refIndirect) {
                m_sensors.push_back({&s, radiosity::locateOnMesh(run.mesh, s.position, s.normal,
                                                                 radiosity::pointNudge(run.scene), run.embree.get())});
                run.convergenceSensors.push_back(s.name);
            }
    }

    /// Whether this push-pull is logged or snapshot (the solver then fills the arrays).
    bool wants(const radiosity::RadiositySolution& solution) const {
        return m_options.logConvergence || snapshotDue(solution);
    }

    void operator()(const radiosity::RadiositySolution& solution) {
        const double fraction = solution.unshotFraction();
        bool last = solution.converged;
        bool log = m_options.logConvergence;
        bool snapshot = snapshotDue(solution);
        if (!log && !snapshot) return;
        radiosity::RadiositySolution copy = solution;
        radiosity::reconstructVertexValues(m_run.scene, m_run.mesh, copy);
        if (log) logRow(copy, fraction, last);
        if (snapshot) writeSnapshot(copy);
    }

  private:
    /// Snapshot k of K when the unshot fraction has come k/K of the way (in log) from
    /// where the solve started to radiosity.stop_unshot, and at the end.
    bool snapshotDue(const radiosity::RadiositySolution& solution) const {
        const double start = solution.initialUnshotFlux / std::max(1e-300, solution.unshotReference());
        const double stop = m_run.scene.shooting.stopUnshot;
        return m_options.snapshots > 0 && m_nextSnapshot <= m_options.snapshots &&
               (solution.converged || solution.unshotFraction() <=
                                          start * std::pow(stop / start, double(m_nextSnapshot) / m_options.snapshots));
    }

    void logRow(const radiosity::RadiositySolution& copy, double fraction, bool last) {
        ConvergenceRow row;
        row.seconds = copy.seconds;
        row.shots = copy.shots;
        row.unshotFraction = fraction;
        // The gather is costly: take it each time the unshot fraction has halved, and last.
        bool gather = last || fraction <= 0.5 * m_lastGatherFraction;
        std::optional<radiosity::Gatherer> gatherer;
        if (gather) {
            m_lastGatherFraction = fraction;
            gatherer.emplace(m_run.scene, m_run.mesh, m_run.lighting.clustering, copy, *m_run.embree,
                             radiosity::GatherOptions::forSensors(m_run.scene, m_run.mesh));
        }
        radiosity::GatherMemo memo;  // the row's sensors share their re-gathers, as a run of the sensor stage does
        for (const auto& [s, where] : m_sensors) {
            std::optional<double> vertex;
            if (where)
                vertex = luminance(radiosity::interpolateIndirect(m_run.mesh, copy, where->patch, where->u, where->v));
            row.vertexErrorPct.push_back(vertex ? errorPct(*vertex, s->refIndirect) : std::nullopt);
            std::optional<double> gathered;
            if (gatherer) {
                Vec3 x = where ? radiosity::nudgeInside(m_run.mesh, where->patch, s->position,
                                                        radiosity::pointNudge(m_run.scene))
                               : s->position;
                gathered = errorPct(luminance(gatherer->indirectAt(x, s->normal, memo)), s->refIndirect);
            }
            row.gatheredErrorPct.push_back(gathered);
        }
        m_run.convergence.push_back(row);
    }

    void writeSnapshot(const radiosity::RadiositySolution& copy) {
        ensureShadingNormals(m_run);
        raytrace::ImageCamera camera(*m_run.scene.camera);
        raytrace::DisplayAverage forDisplay{displayCompression(m_run.scene, m_run.mesh, copy), {}};
        HdrImage image = raytrace::render(m_run.scene, m_run.mesh, copy, *m_run.lighting.lights, *m_run.embree, camera,
                                          m_run.scene.render, {}, &forDisplay);
        std::vector<std::string> paths;
        for (const auto& p : m_options.snapshotOutputs) paths.push_back(snapshotPath(p, m_nextSnapshot));
        stageImages(
            paths, image, forDisplay.image, m_options.display,
            fmt::format("rayrad snapshot {} after {} shots, {:.3g} s", m_nextSnapshot, copy.shots, copy.seconds),
            *m_options.files);
        m_options.files->commit();
        for (const auto& p : paths) fmt::print(stderr, "wrote {}\n", p);
        ++m_nextSnapshot;
    }

    PipelineRun& m_run;
    const PipelineOptions& m_options;
    std::vector<std::pair<const scene::Sensor*, std::optional<radiosity::MeshLocation>>> m_sensors;
    double m_lastGatherFraction = 2.0;
    int m_nextSnapshot = 1;
};

scene::Camera findView(const scene::Scene& scene, const std::string& name) {
    for (const auto& v : scene.views)
        if (v.name == name) return v.camera;
    throw InputError(placeMessage(scene.file, "--camera",
                                  "the scene has no view \"" + name + "\" (it has " + viewNames(scene) + ")"));
}

/// The ray tracer for one camera: the plain average (cd/m²) and the display average.
std::pair<HdrImage, HdrImage> traceImage(PipelineRun& run, const scene::Camera& cam, const std::string& label,
                                         const PipelineOptions& options) {
    ensureShadingNormals(run);
    raytrace::ImageCamera camera(cam);
    Progress progress(label, options.quiet);
    const radiosity::RadiositySolution& solution = run.lighting.solution;
    raytrace::DisplayAverage forDisplay{displayCompression(run.scene, run.mesh, solution), {}};
    // render.indirect "gather": a final gather at each hit, as at a sensor.
    std::unique_ptr<radiosity::Gatherer> gatherer;
    if (run.scene.render.gatherIndirect && run.scene.hasReflectance())
        gatherer = radiosity::sensorGatherer(run.scene, run.mesh, *run.embree, run.lighting,
                                             {nullptr, nullptr, options.quiet});  // timed as part of the ray trace
    HdrImage image = raytrace::render(
        run.scene, run.mesh, solution, *run.lighting.lights, *run.embree, camera, run.scene.render,
        [&](double f) { progress.update(f); }, &forDisplay, options.rowBegin, options.rowEnd, gatherer.get());
    return {std::move(image), std::move(forDisplay.image)};
}

/// The radiosity stage: the direct light, the indirect light, the display values.
void solveLighting(PipelineRun& run, const std::string& sceneFile, const PipelineOptions& options) {
    const radiosity::StageLog log = stageLog(run, options);
    run.lighting = radiosity::solveDirect(run.scene, run.mesh, *run.embree, log);
    if (auto w = backLightWarning(run.scene, run.lighting.solution, run.lighting.lights->emittedFlux())) {
        if (!options.quiet) fmt::print(stderr, "warning: {}: {}\n", sceneFile, *w);
        run.warnings.push_back(*w);
    }
    PushPullObserver observer(run, options);
    radiosity::solveIndirect(run.scene, run.mesh, *run.embree, run.lighting, log,
                             {[&](const auto& s) { return observer.wants(s); }, std::ref(observer)});
    radiosity::reconstructDisplay(run.scene, run.mesh, *run.embree, run.lighting, log);
}

}  // namespace

std::string viewNames(const scene::Scene& scene) {
    std::string out;
    for (size_t i = 0; i < scene.views.size(); ++i)
        out += (i == 0 ? "" : i + 1 == scene.views.size() ? " or " : ", ") + ("\"" + scene.views[i].name + "\"");
    return out.empty() ? "none" : out;
}

RenderedView renderCamera(PipelineRun& run, const std::string& label, const scene::Camera& camera,
                          const PipelineOptions& options) {
    run.report.begin("ray trace (" + label + ")");
    auto [image, display] = traceImage(run, camera, "ray trace " + label, options);
    run.report.end();
    return {label, std::move(image), std::move(display)};
}

RenderedView renderView(PipelineRun& run, const std::string& view, const PipelineOptions& options) {
    return renderCamera(run, view, findView(run.scene, view), options);
}

PipelineRun runPipeline(const std::string& sceneFile, const PipelineOptions& options) {
    return runPipeline(sceneFile, scene::loadScene(sceneFile, options.overrides), options);
}

PipelineRun preparePipeline(const std::string& sceneFile, const scene::SceneDesc& desc, const PipelineOptions& options,
                            std::vector<std::string>* inSolid) {
    PipelineRun run;
    const radiosity::StageLog log = stageLog(run, options);
    run.report.begin("parse + build scene");
    run.scene = buildSceneFrom(desc);
    if (options.lightGroup) scene::keepLightGroup(run.scene, *options.lightGroup);
    if (!options.view.empty()) run.scene.camera = findView(run.scene, options.view);

    checkPatchCount(sceneFile, run.scene);
    run.mesh = radiosity::prepareMesh(run.scene, log);
    // Cost warnings at once: the work they warn of may start next.
    run.warnings = costWarnings(sceneFile, run.scene, run.mesh, options.wantSensors);
    if (!options.quiet)
        for (const auto& w : run.warnings) fmt::print(stderr, "warning: {}: {}\n", sceneFile, w);

    run.report.begin("visibility (Embree BVH)");
    run.embree = raytrace::buildEmbreeScene(run.scene, run.mesh);
    radiosity::findContacts(run.mesh, run.scene, *run.embree);
    for (auto& w : sceneWarnings(run.scene, run.mesh, *run.embree, options.wantSensors, inSolid)) {
        if (!options.quiet) fmt::print(stderr, "warning: {}: {}\n", sceneFile, w);
        run.warnings.push_back(std::move(w));
    }
    return run;
}

PipelineRun runPipeline(const std::string& sceneFile, const scene::SceneDesc& desc, const PipelineOptions& options) {
    std::vector<std::string> inSolid;  // per sensor: why it is no measurement, or ""
    PipelineRun run = preparePipeline(sceneFile, desc, options, &inSolid);
    const radiosity::StageLog log = stageLog(run, options);

    if (options.solutionFile.empty()) {
        solveLighting(run, sceneFile, options);
    } else {
        checkInputFile(options.solutionFile, "solution file");
        radiosity::checkSolutionFileStart(options.solutionFile);
        const std::string bytes = readInputFile(options.solutionFile, "solution file", size_t(1) << 40);
        run.lighting = radiosity::loadSolution(run.scene, run.mesh, bytes, options.solutionFile, log);
    }
    checkSolution(run.lighting.solution, options.solutionFile);

    if (options.wantSensors && !run.scene.sensors.empty()) {
        const auto values = radiosity::gatherSensors(run.scene, run.mesh, *run.embree, run.lighting, log);
        const auto& day = run.scene.daylight;
        for (size_t i = 0; i < values.size(); ++i) {
            run.sensors.push_back(
                {run.scene.sensors[i], values[i], i < inSolid.size() ? inSolid[i] : std::string(), {}});
            // Under a sky without direct sun: the daylight factor against the open sky.
            if (day && !day->hasDirectSun() && day->skyHorizontalIlluminance > 0)
                run.sensors.back().daylightFactor =
                    100 * luminance(values[i].direct + values[i].indirect) / day->skyHorizontalIlluminance;
        }
    } else if (options.wantSensors) {
        run.skipped.push_back("sensors (the scene has none)");
    } else if (!run.scene.sensors.empty()) {
        run.skipped.push_back("sensors (not asked for: --sensors, --report or --grid-picture)");
    }

    if (options.wantSensors && !run.scene.observers.empty()) {
        run.glare = observerGlare(run, options.observerFisheyes);
    } else if (!run.scene.observers.empty()) {
        run.skipped.push_back("glare (not asked for: --sensors or --report)");
    }

    if (options.wantImage) {
        run.report.begin(run.scene.render.gatherIndirect ? "ray trace (indirect: a final gather at each hit)"
                                                         : "ray trace");
        auto [image, display] = traceImage(run, *run.scene.camera, "ray trace", options);
        run.image = std::move(image);
        run.displayImage = std::move(display);
    } else if (!run.scene.camera) {
        run.skipped.push_back("ray trace (no camera)");
    }
    run.report.end();
    return run;
}

std::string stagesSummary(const PipelineRun& run) {
    std::string s = "stages run:";
    for (const auto& st : run.report.stages()) s += " " + st.name + ";";
    if (!run.skipped.empty()) {
        s += "\nstages skipped:";
        for (const auto& k : run.skipped) s += " " + k + ";";
    }
    return s + "\n";
}

}  // namespace rayrad::app

namespace rayrad::app {

std::string convergenceCsv(const PipelineRun& run) {
    std::string s = "seconds,shots,unshot_pct";
    for (const auto& n : run.convergenceSensors) s += fmt::format(",{0}_vertex_err_pct,{0}_gather_err_pct", n);
    s += "\n";
    auto cell = [](const std::optional<double>& v) { return v ? fmt::format("{:.6f}", *v) : std::string(); };
    for (const auto& r : run.convergence) {
        s += fmt::format("{:.6f},{},{:.6g}", r.seconds, r.shots, 100 * r.unshotFraction);
        for (size_t k = 0; k < r.vertexErrorPct.size(); ++k)
            s += "," + cell(r.vertexErrorPct[k]) + "," + cell(r.gatheredErrorPct[k]);
        s += "\n";
    }
    return s;
}

radiosity::EnergyBalance energyBalanceOf(const PipelineRun& run) {
    return radiosity::energyBalance(run.scene, run.mesh, run.lighting.solution, run.lighting.lights->emittedFlux());
}

}  // namespace rayrad::app
