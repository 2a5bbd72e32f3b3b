#include <core/colour_temperature.h>

#include <algorithm>

namespace rayrad {

Rgb colourOfTemperature(double kelvin) {
    const double t = std::clamp(kelvin, kMinColourTemperature, kMaxColourTemperature);
    const double t1 = 1e3 / t, t2 = t1 * t1, t3 = t2 * t1;  // the fit is in powers of 10³/T
    const double x = t <= 4000 ? -0.2661239 * t3 - 0.2343589 * t2 + 0.8776956 * t1 + 0.179910
                               : -3.0258469 * t3 + 2.1070379 * t2 + 0.2226347 * t1 + 0.240390;
    const double x2 = x * x, x3 = x2 * x;
    const double y = t <= 2222   ? -1.1063814 * x3 - 1.34811020 * x2 + 2.18555832 * x - 0.20219683
                     : t <= 4000 ? -0.9549476 * x3 - 1.37418593 * x2 + 2.09137015 * x - 0.16748867
                                 : 3.0817580 * x3 - 5.87338670 * x2 + 3.75112997 * x - 0.37001483;
    const double X = x / y, Y = 1.0, Z = (1 - x - y) / y;
    Rgb rgb(3.2406 * X - 1.5372 * Y - 0.4986 * Z, -0.9689 * X + 1.8758 * Y + 0.0415 * Z,
            0.0557 * X - 0.2040 * Y + 1.0570 * Z);
    rgb = glm::max(rgb, Rgb(0.0));
    return rgb / luminance(rgb);
}

}  // namespace rayrad
