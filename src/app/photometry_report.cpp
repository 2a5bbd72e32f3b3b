#include <app/photometry_report.h>

#include <fmt/format.h>


namespace rayrad::app {

std::string photometryReport(const scene::Photometry& p) {
    static const char* kTypes[] = {"C", "B", "A"};
    std::string out = fmt::format("photometric file: {}\nformat: {}, type {}\n", p.file, p.format,
                                  kTypes[static_cast<int>(p.type)]);
    out += fmt::format("grid: {} vertical angles {:g}–{:g}°, {} horizontal angles {:g}–{:g}°; symmetry {}\n",
                       p.vertical.size(), p.vertical.front(), p.vertical.back(), p.horizontal.size(),
                       p.horizontal.front(), p.horizontal.back(), p.symmetry());
    const double flux = p.integratedFlux();
    out += fmt::format("integrated flux: {:.2f} lm (the table, bilinear, integrated over the sphere)\n", flux);
    if (p.absolute) {
        out += "lamp flux: none stated (absolute photometry: the table is the luminaire's own)\n";
    } else {
        out += fmt::format("lamp flux: {:.2f} lm (as stated", p.lampFlux);
        if (p.lampSets > 0)
            out += fmt::format("; lamp set 1 of {}: {:g} × {}", p.lampSets, p.lampCount,
                               p.lampType.empty() ? std::string("(no type)") : p.lampType);
        out += ")\n";
        out += fmt::format("light output ratio: {:.4f} (integrated / lamp flux)", flux / p.lampFlux);
        if (p.statedLor)
            out += fmt::format("; stated {:.4f} ({:+.2f} %)", *p.statedLor, 100 * (flux / p.lampFlux / *p.statedLor - 1));
        out += "\n";
    }
    const auto peak = p.peak();
    out += fmt::format("peak intensity: {:.1f} cd at vertical {:g}°, horizontal {:g}°\n", peak.candela, peak.verticalDeg,
                       peak.horizontalDeg);
    if (p.round)
        out += fmt::format("luminous opening: round, diameter {:.3f} m, height {:.3f} m\n", p.width, p.height);
    else
        out += fmt::format("luminous opening: {:.3f} m along C0, {:.3f} m along C90, {:.3f} m high\n", p.length, p.width,
                           p.height);
    if (p.inputWatts > 0) out += fmt::format("input power: {:g} W\n", p.inputWatts);
    if (!p.tiltAngles.empty())
        out += fmt::format("tilt: {} angles from {:g}° to {:g}° (applied at 0°)\n", p.tiltAngles.size(), p.tiltAngles.front(),
                           p.tiltAngles.back());
    return out;
}

}  // namespace rayrad::app
