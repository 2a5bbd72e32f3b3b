#include <app/false_colour_output.h>

#include <app/grid_statistics.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace rayrad::app {

tonemap::Picture gridPicture(const std::vector<SensorResult>& results) {
    std::vector<tonemap::Picture> pictures;
    for (const auto& stats : gridStatistics(results)) {
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
                    luminance(r.value.direct + r.value.indirect);
        tonemap::FalseColourOptions o;
        o.unit = "lx";
        o.pixelsPerValue = std::clamp(480 / std::max(nu, nv), 4, 64);
        o.title = fmt::format("{}: Emin {:.0f}, Eavg {:.0f}, Emax {:.0f} lx, U0 {:.2f}{}", stats.grid, stats.minimum,
                              stats.mean, stats.maximum, stats.u0(),
                              stats.excluded ? fmt::format(" ({} inside solids left out)", stats.excluded) : "");
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
