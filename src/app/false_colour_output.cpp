#include <app/false_colour_output.h>

#include <app/grid_statistics.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace rayrad::app {

std::string gridPlanTitle(const GridStatistics& s) {
    const std::string left =
        s.excluded ? fmt::format(" ({} inside solids left out)", s.excluded) : std::string();
    if (!s.dfMean)
        return fmt::format("{}: Emin {:.0f}, Eavg {:.0f}, Emax {:.0f} lx, U0 {:.2f}{}", s.grid, s.minimum, s.mean,
                           s.maximum, s.u0(), left);
    std::string title = fmt::format("{}: daylight factor min {:.2f}, mean {:.2f}, median {:.2f} %, U0 {:.2f}{}", s.grid,
                                    *s.dfMinimum, *s.dfMean, *s.dfMedian, s.u0(), left);
    if (s.dfTarget && s.shareAboveTarget && s.dfTargetMinimum && s.shareAboveTargetMinimum)
        title += fmt::format("\nEN 17037 method 1: DF >= {:.1f} % on {:.0f} % (50 % asked), >= {:.1f} % on {:.0f} % (95 % asked): {}",
                             *s.dfTarget, 100 * *s.shareAboveTarget, *s.dfTargetMinimum,
                             100 * *s.shareAboveTargetMinimum, s.meetsEn17037Minimum() ? "met" : "not met");
    return title;
}

tonemap::Picture gridPicture(const std::vector<SensorResult>& results, std::optional<double> medianExternalIlluminance) {
    std::vector<tonemap::Picture> pictures;
    for (const auto& stats : gridStatistics(results, medianExternalIlluminance)) {
        int nu = 0, nv = 0;
        for (const auto& r : results)
            if (r.sensor.grid == stats.grid)
                nu = std::max(nu, r.sensor.gridU + 1), nv = std::max(nv, r.sensor.gridV + 1);
        if (nu <= 0 || nv <= 0) continue;
        tonemap::ScalarField field;
        field.width = nu;
        field.height = nv;
        field.values.assign(static_cast<size_t>(nu) * nv, std::numeric_limits<double>::quiet_NaN());
        for (const auto& r : results)
            if (r.sensor.grid == stats.grid && r.sensor.gridU >= 0 && r.excluded.empty())  // inside a solid: blank
                field.values[static_cast<size_t>(r.sensor.gridV) * nu + r.sensor.gridU] =
                    stats.dfMean && r.daylightFactor ? *r.daylightFactor : luminance(r.value.direct + r.value.indirect);
        tonemap::FalseColourOptions o;
        o.unit = stats.dfMean ? "%" : "lx";
        o.pixelsPerValue = std::clamp(480 / std::max(nu, nv), 4, 64);
        o.title = gridPlanTitle(stats);
        pictures.push_back(tonemap::renderFalseColour(field, o));
    }
    return pictures.empty() ? tonemap::Picture{} : tonemap::stackPictures(pictures);
}

tonemap::Picture luminancePicture(const HdrImage& image) {
    tonemap::ScalarField field;
    field.width = image.width;
    field.height = image.height;
    field.values.reserve(image.pixels.size());
    for (const auto& p : image.pixels) field.values.push_back(luminance(p));
    tonemap::FalseColourOptions o;
    o.logScale = true;
    o.unit = "cd/m²";
    o.title = "luminance";
    return tonemap::renderFalseColour(field, o);
}

}  // namespace rayrad::app
