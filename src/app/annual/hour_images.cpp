#include <app/annual/hour_images.h>

#include <app/image_output.h>
#include <app/result_checks.h>
#include <core/input_error.h>
#include <tonemap/image_io.h>

#include <fmt/format.h>

namespace rayrad::app {

namespace {

/// sum += w · s, patch by patch (direct mean and corners, indirect).
void addWeighted(radiosity::RadiositySolution& sum, double w, const radiosity::RadiositySolution& s) {
    for (size_t i = 0; i < s.directMean.size(); ++i) {
        sum.directMean[i] += w * s.directMean[i];
        sum.indirect[i] += w * s.indirect[i];
    }
    const float wf = static_cast<float>(w);
    for (size_t i = 0; i < s.directCorner.size(); ++i) sum.directCorner[i] += wf * s.directCorner[i];
}

}  // namespace

void addHourImage(const std::string& text, std::vector<HourImage>& images, OutputFiles& files) {
    const size_t eq = text.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == text.size())
        throw InputError(placeMessage("", "--image", fmt::format("expected MM-DDTHH=FILE, got \"{}\"", text)));
    const std::string hour = text.substr(0, eq), path = text.substr(eq + 1);
    addImageOutputs({path}, files);
    for (HourImage& image : images)
        if (image.hourText == hour) {
            image.paths.push_back(path);
            return;
        }
    images.push_back({hour, {path}, 0});
}

HourSolutions::HourSolutions(const std::vector<HourImage>& images, const std::vector<SkyHour>& skies,
                             const SunLight& sun, int patchCount, size_t meshPatches)
    : m_skies(skies), m_patchCount(patchCount) {
    for (const HourImage& image : images) {
        const SkyHour& h = skies[image.hour];
        m_hours.push_back(image.hour);
        m_sunScale.push_back(h.sunNormal > 0 ? sun.sunScale(h.toSun, h.sunWeights) : 0.0);
        radiosity::RadiositySolution sum;
        sum.directMean.assign(meshPatches, Rgb(0.0));
        sum.indirect.assign(meshPatches, Rgb(0.0));
        sum.directCorner.assign(3 * meshPatches, RgbF(0.0f));
        m_sums.push_back(std::move(sum));
    }
}

void HourSolutions::add(int channel, int sunPatch, const radiosity::RadiositySolution& solution) {
    for (size_t k = 0; k < m_hours.size(); ++k) {
        const SkyHour& h = m_skies[m_hours[k]];
        double w = 0;
        if (channel >= 0) {
            w = channel < m_patchCount ? h.patchLuminance[static_cast<size_t>(channel)] : h.groundLuminance;
        } else {
            for (int n = 0; n < h.sunWeights.count; ++n)
                if (h.sunWeights.patch[n] == sunPatch) w += h.sunNormal * m_sunScale[k] * h.sunWeights.weight[n];
        }
        if (w != 0) addWeighted(m_sums[k], w, solution);
    }
}

RenderedView renderWithSolution(PipelineRun& run, const scene::Daylight& daylight, radiosity::RadiositySolution solution,
                                const scene::Camera& camera, const std::string& label) {
    const std::optional<scene::Daylight> before = run.scene.daylight;
    run.scene.daylight = daylight;
    radiosity::Lighting lighting = radiosity::lightingWith(run.scene, *run.embree, std::move(solution));
    std::swap(run.lighting, lighting);
    const radiosity::StageLog log{&run.report, nullptr, true, nullptr};
    radiosity::reconstructDisplay(run.scene, run.mesh, *run.embree, run.lighting, log);
    PipelineOptions quiet;
    quiet.quiet = true;
    RenderedView view = renderCamera(run, label, camera, quiet);
    std::swap(run.lighting, lighting);
    run.scene.daylight = before;
    return view;
}

void renderHourImage(PipelineRun& run, const scene::WeatherFile& weather, const SkyHour& sky, const HourImage& image,
                     radiosity::RadiositySolution solution, OutputFiles& files) {
    const scene::Daylight daylight = yearHourDaylight(weather, *run.scene.daylight, image.hour, sky);
    const RenderedView view =
        renderWithSolution(run, daylight, std::move(solution), *run.scene.camera, "hour " + image.hourText);
    checkRenderedImage(view.image, false);
    stageImages(image.paths, view.image, view.displayImage, tonemap::DisplayOptions{},
                fmt::format("rayrad rendering of {} in the hour ending {} (weather file {}), from daylight "
                            "coefficients",
                            run.scene.file, image.hourText, weather.city),
                files);
}

}  // namespace rayrad::app
