#include <app/annual/daylight_dimming.h>

#include <core/input_error.h>

#include <algorithm>

namespace rayrad::app {

std::vector<double> lampIlluminance(PipelineRun& run) {
    const scene::Scene& sc = run.scene;
    const bool lamps = !sc.lights.empty() || std::any_of(sc.materials.begin(), sc.materials.end(),
                                                         [](const scene::Material& m) { return m.isEmissive(); });
    if (!lamps)
        throw InputError(placeMessage(sc.file, "", "--dimming: the scene has no lamps to dim (no light, no emissive "
                                                   "material)"));
    const std::optional<scene::Daylight> daylight = run.scene.daylight;
    run.scene.daylight.reset();
    const radiosity::StageLog log{nullptr, nullptr, true, nullptr};
    radiosity::Lighting lighting = radiosity::solveDirect(run.scene, run.mesh, *run.embree, log);
    radiosity::solveIndirect(run.scene, run.mesh, *run.embree, lighting, log);
    const auto values = radiosity::gatherSensors(run.scene, run.mesh, *run.embree, lighting, log);
    run.scene.daylight = daylight;
    std::vector<double> out;
    for (const auto& v : values) out.push_back(luminance(v.direct + v.indirect));
    return out;
}

std::vector<std::optional<double>> dimmingShares(const AnnualStudy& study, const std::vector<double>& lamps,
                                                 double target) {
    std::vector<std::optional<double>> out(study.points);
    for (size_t i = 0; i < study.points; ++i) {
        if (!(lamps[i] > 0)) continue;
        const float* day = &study.total[i * study.hours];
        double sum = 0;
        size_t n = 0;
        for (size_t h = 0; h < study.hours; ++h) {
            if (!study.occupied[h]) continue;
            sum += std::clamp((target - day[h]) / lamps[i], 0.0, 1.0);
            ++n;
        }
        out[i] = n > 0 ? sum / n : 0.0;
    }
    return out;
}

}  // namespace rayrad::app
