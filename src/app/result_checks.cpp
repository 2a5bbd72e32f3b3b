#include <app/result_checks.h>

#include <core/input_error.h>
#include <core/result_error.h>

#include <fmt/format.h>

#include <algorithm>
#include <cfloat>
#include <cmath>

namespace rayrad::app {

void checkRenderedImage(const HdrImage& image, bool allowBlack) {
    size_t bad = 0, lit = 0, firstBad = 0;
    double brightest = 0;
    for (size_t i = 0; i < image.pixels.size(); ++i) {
        const Rgb& p = image.pixels[i];
        bool finite = true;
        for (int c = 0; c < 3; ++c) finite &= std::isfinite(p[c]) && std::abs(p[c]) <= FLT_MAX;
        if (!finite) {
            if (bad++ == 0) firstBad = i;
            continue;
        }
        brightest = std::max(brightest, std::max({p.r, p.g, p.b}));
        lit += p != Rgb(0.0);
    }
    if (bad > 0) {
        const Rgb& p = image.pixels[firstBad];
        throw ResultError(fmt::format(
            "the image has {} pixel(s) that are not finite numbers or exceed an EXR float (3.4e38 cd/m²), the "
            "first at x {}, y {} ({:.4g} {:.4g} {:.4g}): is a light's intensity or luminance absurdly large? "
            "Nothing was written",
            bad, firstBad % image.width, firstBad / image.width, p.r, p.g, p.b));
    }
    if (lit == 0 && !allowBlack)
        throw ResultError(
            "every pixel of the image is black: no light reaches the camera (is it behind a mirror or a one-sided "
            "surface, inside a closed object, or looking away from every lit surface?). Nothing was written; "
            "--allow-black writes it anyway");
}

void checkDisplayImage(const std::string& path, const std::vector<uint8_t>& rgb8, const std::string& exposure) {
    const bool allBlack = std::all_of(rgb8.begin(), rgb8.end(), [](uint8_t v) { return v == 0; });
    const bool allWhite = std::all_of(rgb8.begin(), rgb8.end(), [](uint8_t v) { return v == 255; });
    if (allBlack || allWhite)
        throw ResultError(placeMessage(
            path, "", fmt::format("the exposure ({}) maps every pixel of the rendering to {}, although it has light: "
                                  "try --exposure auto. Nothing was written",
                                  exposure, allBlack ? "black" : "white")));
}

std::vector<std::string> checkSensorResults(const std::vector<SensorResult>& results) {
    bool anyLight = false;
    for (const auto& r : results) {
        anyLight |= r.value.direct != Rgb(0.0) || r.value.indirect != Rgb(0.0);
        const Rgb values[2] = {r.value.direct, r.value.indirect};
        for (const Rgb& v : values)
            for (int c = 0; c < 3; ++c)
                if (!std::isfinite(v[c]))
                    throw ResultError(fmt::format(
                        "sensor \"{}\": its illuminance is not a finite number ({} lx direct, {} lx indirect): is a "
                        "light's intensity or luminance absurdly large? Nothing was written",
                        r.sensor.name, toString(r.value.direct), toString(r.value.indirect)));
    }
    if (results.size() > 1 && !anyLight)
        return {fmt::format("every one of the {} sensors reads 0 lx: are they inside objects, behind surfaces, or "
                            "facing away from every light?", results.size())};
    return {};
}

}  // namespace rayrad::app
