// What a run writes besides its images: the sensor table and its companion files, the
// reports and the false-colour pictures. Every path is checked and added to the run's
// OutputFiles before the work; the contents are given to it after (core/output_file.h).
#pragma once

#include <app/light_group_parts.h>
#include <app/pipeline.h>
#include <core/output_file.h>
#include <scene/scene_desc.h>

#include <optional>
#include <string>
#include <vector>

namespace rayrad::app {

/// The files a run reads (the scene, its mesh and photometric files), so that no output
/// can be one of them.
OutputFiles filesOf(const scene::SceneDesc& desc);

/// Checks and adds each non-empty path.
void addOutputs(OutputFiles& files, const std::vector<std::string>& paths);

/// What `--sensors FILE.csv` writes: the points and, beside them, the grid statistics
/// (when the scene has grids), each light group's part (when its emitters name groups) and
/// the glare at the observers (when it has observers).
struct SensorFiles {
    std::string points, grids, groups, glare;
    std::vector<std::string> all() const;
};
SensorFiles sensorFiles(const scene::SceneDesc& desc, const std::string& csvPath);

/// The report options of solve and render.
struct ReportArgs {
    std::string convergence;  ///< --convergence FILE.csv
    std::string report;       ///< --report FILE.json
    std::string gridPicture;  ///< --grid-picture FILE.png
    std::string falseColour;  ///< render --false-colour FILE.png
    std::string glarePictures;  ///< --glare-pictures DIR: each observer's marked fisheye, DIR/NAME.png
};

/// The sensor files, then the reports (a picture must be PNG or JPEG; a grid picture
/// needs grids): checked and added; all of them, for the "wrote" lines.
std::vector<std::string> addSensorAndReportOutputs(const scene::SceneDesc& desc, const SensorFiles& csvs,
                                                   const ReportArgs& reports, OutputFiles& files);

/// The sensor table, grid statistics and light groups' parts (one more solve per group),
/// on stdout and into the files; returns the groups' parts when the scene has groups and
/// sensors. `forSavedSolution`: the groups are solved even without sensors, and their
/// solutions kept (solve --save).
std::optional<LightGroupParts> reportSensors(PipelineRun& run, const std::string& sceneFile, const PipelineOptions& options,
                                             const SensorFiles& f, OutputFiles& files, bool forSavedSolution = false);

/// The reports' and pictures' contents into the files (`groups`: the light groups' parts
/// for the JSON report, or null).
void stageReports(const PipelineRun& run, const std::string& scene, const ReportArgs& r, const LightGroupParts* groups,
                  OutputFiles& files);

/// "wrote PATH" on stderr for each non-empty path.
void reportWritten(const std::vector<std::string>& paths);

}  // namespace rayrad::app
