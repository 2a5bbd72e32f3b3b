#include <app/run_outputs.h>

#include <app/false_colour_output.h>
#include <app/grid_statistics.h>
#include <app/light_group_parts.h>
#include <app/result_checks.h>
#include <app/run_report.h>
#include <core/input_error.h>
#include <scene/light_groups.h>
#include <tonemap/image_io.h>

#include <fmt/format.h>

#include <algorithm>
#include <iostream>

namespace rayrad::app {

namespace {

bool hasSensorGrids(const scene::SceneDesc& desc) {
    return !desc.surfaceGrids.empty() ||
           std::any_of(desc.sensors.begin(), desc.sensors.end(), [](const auto& s) { return !s.grid.empty(); });
}

/// Checks the report outputs before the work (a picture must be PNG or JPEG; a grid
/// picture needs grids) and adds them; returns them for the "wrote" lines.
std::vector<std::string> addReportOutputs(const scene::SceneDesc& desc, const ReportArgs& r, OutputFiles& files) {
    for (const auto* picture : {&r.gridPicture, &r.falseColour}) {
        if (picture->empty()) continue;
        tonemap::checkImageFormat(*picture);
        if (tonemap::isHdrFormat(*picture))
            throw OutputError(placeMessage(*picture, "", "a false-colour picture is a display image: use .png or .jpg"));
    }
    if (!r.gridPicture.empty() && !hasSensorGrids(desc))
        throw InputError(placeMessage(desc.file, "", "--grid-picture: the scene has no sensor grid or work plane"));
    std::vector<std::string> out{r.convergence, r.report, r.gridPicture, r.falseColour};
    if (!r.glarePictures.empty()) {
        if (desc.observers.empty())
            throw InputError(placeMessage(desc.file, "", "--glare-pictures: the scene has no observers"));
        for (size_t i = 0; i < desc.observers.size(); ++i) out.push_back(glarePicturePath(r.glarePictures, desc.observers, i));
    }
    for (const auto& path : out)
        if (!path.empty()) files.add(path);
    return out;
}

}  // namespace

/// The files a run reads (the scene, its mesh and photometric files), so that no output
/// can be one of them.
OutputFiles filesOf(const scene::SceneDesc& desc) {
    OutputFiles files;
    files.addInput(desc.file);
    for (const auto& o : desc.objects)
        if (!o.resolvedFile.empty()) files.addInput(o.resolvedFile);
    for (const auto& l : desc.lights)
        if (!l.resolvedFile.empty()) files.addInput(l.resolvedFile);
    return files;
}

void addOutputs(OutputFiles& files, const std::vector<std::string>& paths) {
    for (const auto& path : paths)
        if (!path.empty()) files.add(path);
}

std::vector<std::string> SensorFiles::all() const {
    std::vector<std::string> out;
    for (const auto* p : {&points, &grids, &groups, &glare})
        if (!p->empty()) out.push_back(*p);
    return out;
}

SensorFiles sensorFiles(const scene::SceneDesc& desc, const std::string& csvPath) {
    SensorFiles f;
    if (csvPath.empty()) return f;
    f.points = csvPath;
    if (hasSensorGrids(desc)) f.grids = gridSummaryPath(csvPath);
    if ((!desc.sensors.empty() || !desc.surfaceGrids.empty()) && hasLightGroups(desc)) f.groups = lightGroupPath(csvPath);
    if (!desc.observers.empty()) f.glare = observerGlarePath(csvPath);
    return f;
}

/// The sensor table, grid statistics and light groups' parts (one more solve per group),
/// on stdout and into the files.
std::optional<LightGroupParts> reportSensors(PipelineRun& run, const std::string& sceneFile, const PipelineOptions& options,
                                             const SensorFiles& f, OutputFiles& files, bool forSavedSolution) {
    for (const auto& w : checkSensorResults(run.sensors)) fmt::print(stderr, "warning: {}\n", w);
    const auto grids = gridStatistics(
        run.sensors, run.scene.daylight ? run.scene.daylight->medianExternalIlluminance : std::nullopt);
    if (!run.sensors.empty()) std::cout << sensorTable(run.sensors) << gridTable(grids);
    if (!f.points.empty()) files.set(f.points, sensorCsv(run.sensors));
    if (!f.grids.empty()) files.set(f.grids, gridCsv(grids));
    if (!run.glare.empty()) std::cout << "\nglare at the observers (UGR, CIE 117; L_b = E_ind / pi):\n"
                                      << observerGlareTable(run.glare);
    if (!f.glare.empty()) files.set(f.glare, observerGlareCsv(run.glare));
    const auto groups = scene::lightGroups(run.scene);
    if (groups.empty() || (run.sensors.empty() && !forSavedSolution)) return std::nullopt;
    run.report.begin(fmt::format("light groups ({} solves)", groups.size()));
    LightGroupParts parts = solveLightGroups(sceneFile, options, run, groups, forSavedSolution);
    run.report.end();
    if (run.sensors.empty()) return parts;
    std::cout << "\nlight groups (total lx; each group solved alone, the light being linear in the emission):\n"
              << lightGroupTable(run.sensors, parts);
    fmt::print(stderr, "light groups: {} solved alone; their sum differs from the full solve by at most {:.3f} %\n",
               groups.size(), 100 * largestGroupSumDifference(run.sensors, parts));
    if (!f.groups.empty()) files.set(f.groups, lightGroupCsv(run.sensors, parts));
    return parts;
}

void reportWritten(const std::vector<std::string>& paths) {
    for (const auto& path : paths)
        if (!path.empty()) fmt::print(stderr, "wrote {}\n", path);
}

/// The sensor files, then the reports: checked and added; all of them, for the "wrote" lines.
std::vector<std::string> addSensorAndReportOutputs(const scene::SceneDesc& desc, const SensorFiles& csvs,
                                                   const ReportArgs& reports, OutputFiles& files) {
    std::vector<std::string> out = csvs.all();
    addOutputs(files, out);
    const auto more = addReportOutputs(desc, reports, files);
    out.insert(out.end(), more.begin(), more.end());
    return out;
}

void stageReports(const PipelineRun& run, const std::string& scene, const ReportArgs& r, const LightGroupParts* groups,
                  OutputFiles& files) {
    if (!r.convergence.empty()) files.set(r.convergence, convergenceCsv(run));
    if (!r.report.empty()) files.set(r.report, runReportJson(run, scene, groups));
    auto picture = [&](const std::string& path, const tonemap::Picture& p) {
        files.set(path, tonemap::encodeDisplayImage(path, p.width, p.height, p.rgb));
    };
    if (!r.gridPicture.empty())
        picture(r.gridPicture, gridPicture(run.sensors, run.scene.daylight
                                                            ? run.scene.daylight->medianExternalIlluminance
                                                            : std::nullopt));
    if (!r.falseColour.empty() && run.image) picture(r.falseColour, luminancePicture(*run.image));
    if (!r.glarePictures.empty())
        for (size_t i = 0; i < run.glare.size(); ++i)
            if (const auto& m = run.glare[i].marked) {
                const std::string path = glarePicturePath(r.glarePictures, run.scene.observers, i);
                files.set(path, tonemap::encodeDisplayImage(path, m->width, m->height, m->rgb,
                                                            "rayrad: the glare sources seen by observer " +
                                                                run.glare[i].observer.name));
            }
}

}  // namespace rayrad::app
