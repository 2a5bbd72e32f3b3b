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
        // Black as written: an EXR holds floats, in which 1e-300 cd/m² is 0.
        lit += static_cast<float>(p.r) != 0 || static_cast<float>(p.g) != 0 || static_cast<float>(p.b) != 0;
    }
    if (bad > 0) {
        const Rgb& p = image.pixels[firstBad];
        throw ResultError(fmt::format(
            "the image has {} pixel(s) that are not finite numbers or exceed an EXR float (3.4e38 cd/m²), the "
            "first at x {}, y {} ({:.4g} {:.4g} {:.4g}): is a light's intensity or luminance absurdly large? "
            "Nothing was written",
            bad, firstBad % image.width, firstBad / image.width, p.r, p.g, p.b));
    }
    if (lit == 0 && brightest > 0 && !allowBlack)
        throw ResultError(fmt::format(
            "every pixel of the image is black as an EXR float holds it (the brightest is {:.3g} cd/m², below "
            "1.4e-45): is a light's intensity or a group's dimming absurdly small? Nothing was written",
            brightest));
    if (lit == 0 && !allowBlack)
        throw ResultError(
            "every pixel of the image is black: no light reaches the camera (is it behind a mirror or a one-sided "
            "surface, inside a closed object, or looking away from every lit surface?). Nothing was written; "
            "--allow-black writes it anyway");
}

void checkSolution(const radiosity::RadiositySolution& solution, const std::string& solutionFile) {
    auto finite = [](const Rgb& c) { return std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b); };
    auto fail = [&](const std::string& what, size_t index, size_t count) {
        const std::string source = solutionFile.empty() ? "the solution" : solutionFile;
        throw ResultError(fmt::format("{} holds {} non-finite {} value(s), the first at index {}: is a light's "
                                      "intensity or luminance absurdly large? Nothing was written",
                                      source, count, what, index));
    };
    auto scan = [&](const std::vector<Rgb>& values, const std::string& what) {
        size_t bad = 0, first = 0;
        for (size_t i = 0; i < values.size(); ++i)
            if (!finite(values[i]) && bad++ == 0) first = i;
        if (bad > 0) fail(what, first, bad);
    };
    scan(solution.directMean, "direct patch");
    scan(solution.indirect, "indirect patch");
    scan(solution.vertexIndirect, "vertex");
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
