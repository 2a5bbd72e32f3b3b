// Images of hours of the year from the daylight coefficients: each channel's whole solution
// weighted by the hour's sky and sun, the ray tracer lighting it directly with that hour's
// sky and sun, without a solve of the hour.
#pragma once

#include <app/annual/annual_skies.h>
#include <app/annual/sun_light.h>
#include <app/pipeline.h>
#include <core/output_file.h>
#include <scene/daylight/weather_file.h>

#include <string>
#include <vector>

namespace rayrad::app {

/// The --image MM-DDTHH=FILE of one hour: the hour (filled once the year's skies are known)
/// and its files.
struct HourImage {
    std::string hourText;            ///< "MM-DDTHH"
    std::vector<std::string> paths;
    size_t hour = 0;                 ///< 0-based hour of the year
};

/// Splits "MM-DDTHH=FILE" (InputError naming --image otherwise), checks the file's format
/// and adds it to `files`; a file for an hour already in `images` joins it (one rendering).
void addHourImage(const std::string& text, std::vector<HourImage>& images, OutputFiles& files);

/// The solutions of the requested hours, summed as the channels are solved:
///   S_h = Σ_c L_c(h) S_c + E_n(h) k(h) Σ_j w_j(h) S_sun,j
/// (L_c the hour's tent-weighted luminance of sky channel c, or the ground's; the sun's
/// interreflected light as the sensors take it: SunLight::sunScale, hourParts).
class HourSolutions {
  public:
    HourSolutions(const std::vector<HourImage>& images, const std::vector<SkyHour>& skies, const SunLight& sun,
                  int patchCount, size_t meshPatches);
    /// Adds channel c's solution (sunPatch −1), or the sun's at patch sunPatch's centre (c −1).
    void add(int channel, int sunPatch, const radiosity::RadiositySolution& solution);
    const radiosity::RadiositySolution& solution(size_t image) const { return m_sums[image]; }

  private:
    std::vector<size_t> m_hours;
    const std::vector<SkyHour>& m_skies;
    std::vector<double> m_sunScale;  ///< k(h) per image
    int m_patchCount;
    std::vector<radiosity::RadiositySolution> m_sums;
};

/// `camera` lit by `daylight` (an hour's sky and sun, for the ray tracer's direct light) with
/// `solution` in place of a solve (vertex values and seam profiles reconstructed from it;
/// stage "ray trace (LABEL)"). run's daylight and lighting are put back after.
RenderedView renderWithSolution(PipelineRun& run, const scene::Daylight& daylight, radiosity::RadiositySolution solution,
                                const scene::Camera& camera, const std::string& label);

/// The scene's camera in hour `image.hour` of `weather` from its summed `solution`, checked
/// and staged into `files`.
void renderHourImage(PipelineRun& run, const scene::WeatherFile& weather, const SkyHour& sky, const HourImage& image,
                     radiosity::RadiositySolution solution, OutputFiles& files);

}  // namespace rayrad::app
