#include <app/compare.h>

#include <core/input_error.h>
#include <core/input_file.h>
#include <core/output_file.h>
#include <core/result_error.h>
#include <core/text.h>
#include <scene/json_reader.h>
#include <tonemap/display_transform.h>
#include <tonemap/false_colour.h>
#include <tonemap/image_alignment.h>
#include <tonemap/image_io.h>
#include <tonemap/image_metrics.h>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <iostream>
#include <map>

namespace rayrad::app {

namespace {

using tonemap::ErrorFigures;
using tonemap::Region;

/// The image in linear Rec.709: EXR and HDR as stored, PNG/JPEG decoded from sRGB, unless
/// the option says otherwise.
HdrImage readLinear(const std::string& path, const std::string& space, const char* option) {
    if (space != "auto" && space != "linear" && space != "srgb")
        throw InputError(placeMessage("", option, "expected auto, linear or srgb, got \"" + space + "\""));
    checkInputFile(path, "image");
    HdrImage img = tonemap::readImage(path);
    const std::string ext = lowerExtension(path);
    const bool encoded = space == "srgb" || (space == "auto" && ext != ".exr" && ext != ".hdr");
    return encoded ? tonemap::linearFromSrgb(img) : img;
}

nlohmann::json readJson(const std::string& path, const char* what) {
    const std::string text = readInputFile(path, what, size_t(1) << 20);
    if (const size_t at = scene::tooDeepAt(text); at != std::string::npos)
        throw InputError(placeMessage(path, fmt::format("byte {}", at),
                                      fmt::format("arrays and objects nested more than {} levels deep",
                                                  scene::kMaxJsonDepth)));
    try {
        return nlohmann::json::parse(text);
    } catch (const nlohmann::json::parse_error& e) {
        throw InputError(placeMessage(path, "", std::string("not JSON: ") + e.what()));
    }
}

/// [{"a": [x, y], "b": [x, y]}, ...]: the same point in a and in b, pixels from the top-left.
std::vector<tonemap::PointPair> readPointPairs(const std::string& path) {
    const nlohmann::json j = readJson(path, "alignment file");
    if (!j.is_array()) throw InputError(placeMessage(path, "", "expected an array of {\"a\": [x, y], \"b\": [x, y]}"));
    std::vector<tonemap::PointPair> pairs;
    for (size_t i = 0; i < j.size(); ++i) {
        try {
            const auto a = j[i].at("a").get<std::array<double, 2>>(), b = j[i].at("b").get<std::array<double, 2>>();
            for (double v : {a[0], a[1], b[0], b[1]})
                if (!std::isfinite(v)) throw std::invalid_argument("not finite");
            pairs.push_back({a[0], a[1], b[0], b[1]});
        } catch (const std::exception&) {
            throw InputError(placeMessage(path, "/" + std::to_string(i),
                                          "expected {\"a\": [x, y], \"b\": [x, y]} with finite numbers"));
        }
    }
    return pairs;
}

std::vector<Region> readRegions(const std::string& path, int width, int height) {
    std::vector<Region> regions{{"image", 0, 0, width, height}};
    if (path.empty()) return regions;
    const nlohmann::json j = readJson(path, "regions file");
    if (!j.is_array())
        throw InputError(
            placeMessage(path, "", "expected an array of {\"name\", \"x\", \"y\", \"width\", \"height\"}"));
    for (size_t i = 0; i < j.size(); ++i) {
        const std::string where = "/" + std::to_string(i);
        const auto& e = j[i];
        Region r;
        try {
            r.name = e.at("name").get<std::string>();
            r.x = e.at("x").get<int>(), r.y = e.at("y").get<int>();
            r.width = e.at("width").get<int>(), r.height = e.at("height").get<int>();
        } catch (const nlohmann::json::exception&) {
            throw InputError(
                placeMessage(path, where, "expected {\"name\": text, \"x\", \"y\", \"width\", \"height\": integers}"));
        }
        if (r.x < 0 || r.y < 0 || r.width <= 0 || r.height <= 0 || r.x + r.width > width || r.y + r.height > height)
            throw InputError(placeMessage(path, where,
                                          fmt::format("the region {},{} {}×{} is not inside the {}×{} images", r.x, r.y,
                                                      r.width, r.height, width, height)));
        regions.push_back(r);
    }
    return regions;
}

/// The value of a named figure, for --fail-above.
double figure(const ErrorFigures& f, const std::string& metric) {
    if (metric == "mean_abs_rel_pct") return f.meanAbsRelPct;
    if (metric == "median_abs_rel_pct") return f.medianAbsRelPct;
    if (metric == "p95_abs_rel_pct") return f.p95AbsRelPct;
    if (metric == "rms_log") return f.rmsLog;
    if (metric == "ssim_loss") return 1 - f.ssim;
    if (metric == "mean_flip") return f.meanFlip;
    if (metric == "abs_mean_rel_pct") return std::abs(f.meanRelPct);
    if (metric == "mean_delta_e2000") return f.meanDeltaE2000;
    if (metric == "p95_delta_e2000") return f.p95DeltaE2000;
    throw InputError(placeMessage("", "--fail-above",
                                  "unknown metric \"" + metric +
                                      "\" (mean_abs_rel_pct, median_abs_rel_pct, p95_abs_rel_pct, abs_mean_rel_pct, "
                                      "rms_log, ssim_loss, mean_flip, "
                                      "mean_delta_e2000, p95_delta_e2000)"));
}

struct Bound {
    std::string metric;
    double value;
};

std::vector<Bound> parseBounds(const std::vector<std::string>& specs) {
    std::vector<Bound> out;
    for (const auto& s : specs) {
        const size_t eq = s.find('=');
        double v = 0;
        size_t used = 0;
        try {
            if (eq != std::string::npos) v = std::stod(s.substr(eq + 1), &used);
        } catch (const std::exception&) {
            used = 0;
        }
        if (eq == std::string::npos || used == 0 || used != s.size() - eq - 1 || !std::isfinite(v))
            throw InputError(placeMessage("", "--fail-above", "expected METRIC=VALUE, got \"" + s + "\""));
        Bound b{s.substr(0, eq), v};
        figure(ErrorFigures{}, b.metric);  // a known name
        out.push_back(b);
    }
    return out;
}

tonemap::Picture sideBySide(const HdrImage& a, const HdrImage& b) {
    tonemap::DisplayOptions d;
    d.autoExposure = false;
    const double average = tonemap::logAverageLuminance(b);
    d.exposureStops = average > 0 ? std::log2(0.18 / average) : 0;
    const auto pa = tonemap::toDisplay(a, d), pb = tonemap::toDisplay(b, d);
    constexpr int kGap = 8;
    tonemap::Picture p;
    p.width = 2 * a.width + kGap, p.height = a.height;
    p.rgb.assign(static_cast<size_t>(p.width) * p.height * 3, 255);
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x)
            for (int c = 0; c < 3; ++c) {
                const size_t src = (static_cast<size_t>(y) * a.width + x) * 3 + c;
                p.rgb[(static_cast<size_t>(y) * p.width + x) * 3 + c] = pa[src];
                p.rgb[(static_cast<size_t>(y) * p.width + a.width + kGap + x) * 3 + c] = pb[src];
            }
    return p;
}

/// The pictures and reports compare writes, checked before any work.
void addPictureAndReportOutputs(const CompareOptions& o, OutputFiles& files) {
    for (const auto* path : {&o.diffMap, &o.sideBySide}) {
        if (path->empty()) continue;
        files.add(*path);
        tonemap::checkImageFormat(*path);
        if (tonemap::isHdrFormat(*path))
            throw OutputError(placeMessage(*path, "", "a picture is a display image: use .png or .jpg"));
    }
    for (const auto* path : {&o.report, &o.csv})
        if (!path->empty()) files.add(*path);
}

/// The figures as the console shows them (printed), as CSV and as JSON.
struct Tables {
    std::string csv;
    nlohmann::json json;
};

Tables tabulate(const CompareOptions& o, const HdrImage& b, const std::vector<Region>& regions,
                const std::vector<ErrorFigures>& figures, const std::array<double, 3>& factors,
                const std::vector<tonemap::PointPair>& pairs, const tonemap::Homography& homography, double residual) {
    fmt::print("{} against {} ({}×{}); calibration {} over {}: factors {:.5g} {:.5g} {:.5g}\n", o.a, o.b, b.width,
               b.height, o.calibrate, regions.size() > 1 ? "the regions" : "the image", factors[0], factors[1],
               factors[2]);
    if (!pairs.empty())
        fmt::print("aligned by a homography through {} point pairs (largest residual {:.3g} px)\n", pairs.size(),
                   residual);
    fmt::print("{:<16} {:>9} {:>9} {:>9} {:>9} {:>9} {:>8} {:>7} {:>7} {:>7} {:>7}\n", "region", "pixels", "mean %",
               "|mean| %", "median %", "p95 %", "rms ln", "SSIM", "ΔE00", "ΔE00 95", "FLIP");
    std::string csv =
        "region,pixels,mean_rel_pct,mean_abs_rel_pct,median_abs_rel_pct,p95_abs_rel_pct,rms_log,ssim,"
        "mean_delta_e2000,p95_delta_e2000,mean_flip\n";
    nlohmann::json j;
    j["a"] = o.a, j["b"] = o.b, j["width"] = b.width, j["height"] = b.height;
    j["calibration"] = {{"kind", o.calibrate}, {"factors", factors}};
    if (!pairs.empty())
        j["alignment"] = {
            {"pairs", pairs.size()}, {"homography_b_to_a", homography}, {"largest_residual_px", residual}};
    j["regions"] = nlohmann::json::array();
    for (size_t i = 0; i < regions.size(); ++i) {
        const auto& f = figures[i];
        fmt::print("{:<16} {:>9} {:>+9.3f} {:>9.3f} {:>9.3f} {:>9.3f} {:>8.4f} {:>7.4f} {:>7.3f} {:>7.3f} {:>7.4f}\n",
                   regions[i].name.substr(0, 16), f.pixels, f.meanRelPct, f.meanAbsRelPct, f.medianAbsRelPct,
                   f.p95AbsRelPct, f.rmsLog, f.ssim, f.meanDeltaE2000, f.p95DeltaE2000, f.meanFlip);
        csv += fmt::format("{},{},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g}\n", regions[i].name,
                           f.pixels, f.meanRelPct, f.meanAbsRelPct, f.medianAbsRelPct, f.p95AbsRelPct, f.rmsLog, f.ssim,
                           f.meanDeltaE2000, f.p95DeltaE2000, f.meanFlip);
        j["regions"].push_back({{"name", regions[i].name},
                                {"x", regions[i].x},
                                {"y", regions[i].y},
                                {"width", regions[i].width},
                                {"height", regions[i].height},
                                {"pixels", f.pixels},
                                {"mean_rel_pct", f.meanRelPct},
                                {"mean_abs_rel_pct", f.meanAbsRelPct},
                                {"median_abs_rel_pct", f.medianAbsRelPct},
                                {"p95_abs_rel_pct", f.p95AbsRelPct},
                                {"rms_log", f.rmsLog},
                                {"ssim", f.ssim},
                                {"mean_delta_e2000", f.meanDeltaE2000},
                                {"p95_delta_e2000", f.p95DeltaE2000},
                                {"mean_flip", f.meanFlip}});
    }
    return {csv, j};
}

/// |a − b| / b after calibration in false colour, scaled to the larger of 10 % and twice p95.
tonemap::Picture differenceMap(const HdrImage& a, const HdrImage& b, const ErrorFigures& whole) {
    tonemap::ScalarField field{b.width, b.height, tonemap::relativeDifferencePct(a, b)};
    double top = 0;
    for (double v : field.values)
        if (std::isfinite(v)) top = std::max(top, v);
    tonemap::FalseColourOptions fc;
    fc.maximum = std::max(1.0, std::min(top, std::max(10.0, 2 * whole.p95AbsRelPct)));
    fc.title = fmt::format("|a - b| / b after calibration; mean {:.2f} %, p95 {:.2f} %", whole.meanAbsRelPct,
                           whole.p95AbsRelPct);
    fc.unit = "%";
    return tonemap::renderFalseColour(field, fc);
}

}  // namespace

namespace {
/// Of b's pixels, the share the aligned a must cover for a comparison to mean anything.
constexpr double kMinOverlap = 0.1;

/// An image a comparison can be made with: every value finite, not every pixel black.
/// Throws ResultError naming `path` (exit 4): figures over NaN are read as 0 over 0 pixels,
/// and a bound would pass them.
void checkComparable(const HdrImage& image, const std::string& path) {
    size_t nonFinite = 0, lit = 0;
    for (const Rgb& p : image.pixels) {
        if (!std::isfinite(p.r) || !std::isfinite(p.g) || !std::isfinite(p.b))
            ++nonFinite;
        else if (p.r != 0 || p.g != 0 || p.b != 0)
            ++lit;
    }
    if (nonFinite > 0)
        throw ResultError(placeMessage(path, "", fmt::format("{} of its {} pixels are not finite (NaN or Inf): "
                                                             "no figure over it can be trusted",
                                                             nonFinite, image.pixels.size())));
    if (lit == 0) throw ResultError(placeMessage(path, "", "every pixel is black: there is nothing to compare"));
}
}  // namespace

int compareImages(const CompareOptions& o) {
    const auto start = std::chrono::steady_clock::now();
    const std::clock_t cpuStart = std::clock();
    if (o.calibrate != "none" && o.calibrate != "exposure" && o.calibrate != "channels")
        throw InputError(
            placeMessage("", "--calibrate", "expected none, exposure or channels, got \"" + o.calibrate + "\""));
    const std::vector<Bound> bounds = parseBounds(o.failAbove);
    OutputFiles files;
    files.addInput(o.a);
    files.addInput(o.b);
    if (!o.regionsFile.empty()) files.addInput(o.regionsFile);
    if (!o.alignFile.empty()) files.addInput(o.alignFile);
    const std::vector<tonemap::PointPair> pairs =
        o.alignFile.empty() ? std::vector<tonemap::PointPair>{} : readPointPairs(o.alignFile);
    tonemap::Homography homography{};
    if (!pairs.empty()) {
        try {
            homography = tonemap::fitHomography(pairs);
        } catch (const InputError& e) {
            throw InputError(placeMessage(o.alignFile, "", e.what()));
        }
    }
    addPictureAndReportOutputs(o, files);

    HdrImage a = readLinear(o.a, o.aSpace, "--a-space");
    const HdrImage b = readLinear(o.b, o.bSpace, "--b-space");
    checkComparable(a, o.a);
    checkComparable(b, o.b);
    // Alignment: a resampled onto b's grid through the homography (NaN outside a).
    double residual = 0;  // px in a: how far the fitted map misses the given points
    if (!pairs.empty()) {
        for (const auto& p : pairs) {
            const auto m = tonemap::mapPoint(homography, p.bx, p.by);
            residual = std::max(residual, std::hypot(m[0] - p.ax, m[1] - p.ay));
        }
        a = tonemap::warpOnto(a, homography, b.width, b.height);
        size_t covered = 0;
        for (const Rgb& p : a.pixels) covered += std::isfinite(p.r);
        const double share = static_cast<double>(covered) / static_cast<double>(a.pixels.size());
        if (share < kMinOverlap)
            throw ResultError(placeMessage(o.alignFile, "",
                                           fmt::format("the alignment maps {} onto {:.1f} % of {}, less than the "
                                                       "{:.0f} % a comparison needs (are the points' a and b "
                                                       "swapped, or in another image's pixels?)",
                                                       o.a, 100 * share, o.b, 100 * kMinOverlap)));
    } else if (a.width != b.width || a.height != b.height) {
        throw InputError(placeMessage(o.a, "",
                                      fmt::format("is {}×{} but {} is {}×{}: give --align with four or more "
                                                  "corresponding points, or images of one size",
                                                  a.width, a.height, o.b, b.width, b.height)));
    }
    const std::vector<Region> regions = readRegions(o.regionsFile, b.width, b.height);

    // Calibration, a scaled onto b: over the named regions when there are any (the parts
    // the user trusts: aligned, not in a lamp's glare), else over the whole image.
    const std::vector<Region> calibrationRegions =
        regions.size() > 1 ? std::vector<Region>(regions.begin() + 1, regions.end()) : regions;
    std::array<double, 3> factors{1, 1, 1};
    if (o.calibrate == "exposure") factors.fill(tonemap::exposureFactor(a, b, calibrationRegions));
    if (o.calibrate == "channels") factors = tonemap::channelFactors(a, b, calibrationRegions);
    for (auto& p : a.pixels)
        for (int c = 0; c < 3; ++c) p[c] *= factors[c];

    std::vector<ErrorFigures> figures;
    for (const auto& r : regions) figures.push_back(tonemap::compareImages(a, b, r));

    // Console, CSV, JSON.
    const Tables tables = tabulate(o, b, regions, figures, factors, pairs, homography, residual);
    const std::string& csv = tables.csv;
    nlohmann::json j = tables.json;
    // The bounds, on the whole image.
    int status = 0;
    j["bounds"] = nlohmann::json::array();
    for (const auto& bound : bounds) {
        const double v = figure(figures[0], bound.metric);
        const bool exceeded = v > bound.value;
        j["bounds"].push_back({{"metric", bound.metric}, {"bound", bound.value}, {"value", v}, {"exceeded", exceeded}});
        if (exceeded) {
            fmt::print(stderr, "compare: {} = {:.6g} exceeds {:g}\n", bound.metric, v, bound.value);
            status = 1;
        }
    }
    if (!o.report.empty()) files.set(o.report, j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
    if (!o.csv.empty()) files.set(o.csv, csv);
    if (!o.diffMap.empty()) {
        const auto picture = differenceMap(a, b, figures[0]);
        files.set(o.diffMap, tonemap::encodeDisplayImage(o.diffMap, picture.width, picture.height, picture.rgb));
    }
    if (!o.sideBySide.empty()) {
        const auto picture = sideBySide(a, b);
        files.set(o.sideBySide, tonemap::encodeDisplayImage(o.sideBySide, picture.width, picture.height, picture.rgb));
    }
    files.commit();
    for (const auto* path : {&o.diffMap, &o.sideBySide, &o.report, &o.csv})
        if (!path->empty()) fmt::print(stderr, "wrote {}\n", *path);
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    fmt::print(stderr, "compare: {:.2f} s wall, {:.2f} CPU-s\n", wall,
               static_cast<double>(std::clock() - cpuStart) / CLOCKS_PER_SEC);
    return status;
}

}  // namespace rayrad::app
