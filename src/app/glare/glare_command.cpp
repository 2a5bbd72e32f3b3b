#include <app/glare/glare_command.h>

#include <app/glare/fisheye_glare.h>
#include <core/input_error.h>
#include <core/input_file.h>
#include <core/output_file.h>
#include <tonemap/image_io.h>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <iostream>

namespace rayrad::app {

namespace {

std::string glareJson(const GlareArgs& args, const HdrImage& image, const FisheyeGlare& g) {
    using nlohmann::json;
    json j = {{"image", args.image},
              {"width", image.width},
              {"height", image.height},
              {"threshold_cd_m2", g.threshold},
              {"mean_luminance_cd_m2", g.meanLuminance},
              {"ev_lx", g.verticalIlluminance},
              {"ev_sources_lx", g.sourceIlluminance},
              {"background_cd_m2", g.backgroundLuminance},
              {"ugr", g.ugr ? json(*g.ugr) : json(nullptr)},
              {"dgp", g.dgp},
              {"dgp_class", dgpClass(g.dgp)},
              {"sources", json::array()}};
    for (const auto& s : g.sources)
        j["sources"].push_back({{"name", s.name},
                                {"luminance_cd_m2", s.luminance},
                                {"solid_angle_sr", s.solidAngle},
                                {"position_index", s.positionIndex},
                                {"direction", {s.direction.x, s.direction.y, s.direction.z}}});
    return j.dump(2, ' ', false, json::error_handler_t::replace) + "\n";
}

}  // namespace

int runGlare(const GlareArgs& args) {
    OutputFiles files;
    files.addInput(args.image);
    if (!args.marked.empty()) {
        tonemap::checkImageFormat(args.marked);
        if (tonemap::isHdrFormat(args.marked))
            throw OutputError(placeMessage(args.marked, "", "the marked fisheye is a display image: use .png or .jpg"));
        files.add(args.marked);
    }
    if (!args.report.empty()) files.add(args.report);
    if (args.threshold && !(*args.threshold > 0))
        throw InputError(placeMessage("", "--threshold", "expected a luminance above 0 cd/m²"));

    checkInputFile(args.image, "image");
    const HdrImage image = tonemap::readImage(args.image);
    const FisheyeGlare g = analyseFisheye(image, {args.threshold, args.thresholdFactor}, args.image);

    fmt::print("fisheye: {} ({} x {}), field mean {:.4g} cd/m2, sources above {:.4g} cd/m2{}\n", args.image,
               image.width, image.height, g.meanLuminance, g.threshold,
               args.threshold ? "" : fmt::format(" ({:g} x the mean)", args.thresholdFactor));
    fmt::print("vertical illuminance at the eye Ev {:.4g} lx (from the sources {:.4g} lx); background L_b {:.4g} cd/m2\n",
               g.verticalIlluminance, g.sourceIlluminance, g.backgroundLuminance);
    fmt::print("DGP {:.3f} ({}); UGR {}\n", g.dgp, dgpClass(g.dgp),
               g.ugr ? fmt::format("{:.1f}", *g.ugr) : std::string("- (no source within UGR's field)"));
    if (!g.sources.empty()) {
        fmt::print("{:>6} {:>12} {:>10} {:>6} {:>24}\n", "source", "L cd/m2", "omega sr", "P", "direction (right, up, ahead)");
        for (const auto& s : g.sources)
            fmt::print("{:>6} {:>12.5g} {:>10.4g} {:>6.2f}   ({:+.3f}, {:+.3f}, {:+.3f})\n", s.name, s.luminance,
                       s.solidAngle, s.positionIndex, s.direction.x, s.direction.y, s.direction.z);
    }
    if (!args.marked.empty()) {
        const MarkedPicture m = markGlareSources(image, g);
        files.set(args.marked, tonemap::encodeDisplayImage(args.marked, m.width, m.height, m.rgb,
                                                           "rayrad glare: the sources of " + args.image));
    }
    if (!args.report.empty()) files.set(args.report, glareJson(args, image, g));
    files.commit();
    for (const auto* path : {&args.marked, &args.report})
        if (!path->empty()) fmt::print(stderr, "wrote {}\n", *path);
    return 0;
}

}  // namespace rayrad::app
