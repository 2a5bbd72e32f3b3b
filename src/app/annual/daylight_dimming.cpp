#include <app/annual/daylight_dimming.h>

#include <core/input_error.h>
#include <scene/light_groups.h>

#include <algorithm>

namespace rayrad::app {

std::vector<double> lampIlluminance(PipelineRun& run, const std::optional<std::string>& group) {
    const scene::Scene& sc = run.scene;
    const bool lamps = !sc.lights.empty() || std::any_of(sc.materials.begin(), sc.materials.end(),
                                                         [](const scene::Material& m) { return m.isEmissive(); });
    if (!lamps)
        throw InputError(placeMessage(sc.file, "", "--dimming: the scene has no lamps to dim (no light, no emissive "
                                                   "material)"));
    const std::optional<scene::Daylight> daylight = run.scene.daylight;
    const std::vector<scene::PointLight> lights = run.scene.lights;
    const std::vector<scene::Material> materials = run.scene.materials;
    if (group) scene::keepLightGroup(run.scene, *group);
    run.scene.daylight.reset();
    const radiosity::StageLog log{nullptr, nullptr, true, nullptr};
    radiosity::Lighting lighting = radiosity::solveDirect(run.scene, run.mesh, *run.embree, log);
    radiosity::solveIndirect(run.scene, run.mesh, *run.embree, lighting, log);
    const auto values = radiosity::gatherSensors(run.scene, run.mesh, *run.embree, lighting, log);
    run.scene.daylight = daylight;
    run.scene.lights = lights;
    run.scene.materials = materials;
    std::vector<double> out;
    for (const auto& v : values) out.push_back(luminance(v.direct + v.indirect));
    return out;
}

namespace {

/// At point i, lamps giving `lamp` lx at full output: the mean over the occupied hours of
/// d = min(1, max(0, (target − E_day) / lamp)).
double meanOutput(const AnnualStudy& study, size_t i, double lamp, double target) {
    const float* day = &study.total[i * study.hours];
    double sum = 0;
    size_t n = 0;
    for (size_t h = 0; h < study.hours; ++h) {
        if (!study.occupied[h]) continue;
        sum += std::clamp((target - day[h]) / lamp, 0.0, 1.0);
        ++n;
    }
    return n > 0 ? sum / n : 0.0;
}

}  // namespace

std::vector<std::optional<double>> dimmingShares(const AnnualStudy& study, const std::vector<double>& lamps,
                                                 double target) {
    std::vector<std::optional<double>> out(study.points);
    for (size_t i = 0; i < study.points; ++i)
        if (lamps[i] > 0) out[i] = meanOutput(study, i, lamps[i], target);
    return out;
}

std::vector<GroupDimming> dimmingControls(const std::vector<scene::Sensor>& sensors,
                                          const std::vector<std::string>& groups,
                                          const std::vector<std::vector<double>>& groupLamps,
                                          const std::vector<std::string>& controls) {
    std::vector<GroupDimming> out(groups.size());
    for (size_t g = 0; g < groups.size(); ++g) {
        out[g].group = groups[g];
        const auto& lamps = groupLamps[g];
        out[g].control = static_cast<size_t>(std::max_element(lamps.begin(), lamps.end()) - lamps.begin());
    }
    for (const std::string& c : controls) {
        const size_t eq = c.find('=');
        if (eq == std::string::npos)
            throw InputError(placeMessage("", "--dimming-control", "expected GROUP=SENSOR, got \"" + c + "\""));
        const std::string group = c.substr(0, eq), sensor = c.substr(eq + 1);
        const auto g = std::find(groups.begin(), groups.end(), group);
        if (g == groups.end() || group.empty())
            throw InputError(placeMessage("", "--dimming-control", "the scene has no light group \"" + group + "\""));
        const auto s =
            std::find_if(sensors.begin(), sensors.end(), [&](const scene::Sensor& x) { return x.name == sensor; });
        if (s == sensors.end())
            throw InputError(placeMessage("", "--dimming-control", "the scene has no sensor \"" + sensor + "\""));
        out[static_cast<size_t>(g - groups.begin())].control = static_cast<size_t>(s - sensors.begin());
    }
    for (size_t g = 0; g < groups.size(); ++g) out[g].controlIlluminance = groupLamps[g][out[g].control];
    return out;
}

void dimGroups(const AnnualStudy& study, double target, std::vector<GroupDimming>& groups) {
    for (GroupDimming& d : groups)
        if (d.controlIlluminance > 0) d.energyShare = meanOutput(study, d.control, d.controlIlluminance, target);
}

}  // namespace rayrad::app
