#include <app/glare/ugr_table.h>

#include <app/glare/glare_formulas.h>
#include <app/glare/observer_glare.h>
#include <core/input_error.h>

#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <cmath>

namespace rayrad::app {

const std::array<UgrTableRoom, 19> kUgrTableRooms = {{{2, 2},
                                                      {2, 3},
                                                      {2, 4},
                                                      {2, 6},
                                                      {2, 8},
                                                      {2, 12},
                                                      {4, 2},
                                                      {4, 3},
                                                      {4, 4},
                                                      {4, 6},
                                                      {4, 8},
                                                      {4, 12},
                                                      {8, 4},
                                                      {8, 6},
                                                      {8, 8},
                                                      {8, 12},
                                                      {12, 4},
                                                      {12, 6},
                                                      {12, 8}}};

const std::array<RoomReflectances, 5> kUgrTableReflectances = {
    {{0.7, 0.5, 0.2}, {0.7, 0.3, 0.2}, {0.5, 0.5, 0.2}, {0.5, 0.3, 0.2}, {0.3, 0.3, 0.2}}};

namespace {

constexpr double kMaxLateralRatio = 3;  // T/R beyond this: outside the field (CIE 117)
constexpr double kMaxGammaDeg = 85;     // γ beyond this: seen edge-on, left out (CIE 117)

/// Form factor between two directly opposed parallel rectangles a × b at distance c.
double parallelRectangles(double a, double b, double c) {
    const double x = a / c, y = b / c, x2 = x * x, y2 = y * y;
    return 2 / (kPi * x * y) *
           (0.5 * std::log((1 + x2) * (1 + y2) / (1 + x2 + y2)) + x * std::sqrt(1 + y2) * std::atan(x / std::sqrt(1 + y2)) +
            y * std::sqrt(1 + x2) * std::atan(y / std::sqrt(1 + x2)) - x * std::atan(x) - y * std::atan(y));
}

/// A direction of the distribution's quadrature in the room and the flux I ω it carries.
struct FluxCell {
    Vec3 direction;
    double flux;
};

/// The distribution on 1° × 5° cells (γ, C), turned into the room: nadir down, C0 along
/// `c0`. I at each cell's centre times the cell's solid angle (cos γ₀ − cos γ₁) ΔC.
std::vector<FluxCell> fluxCells(const scene::Photometry& p, const Vec3& c0) {
    const Vec3 nadir(0, 0, -1), c90 = glm::cross(-nadir, c0);
    constexpr double dGamma = kPi / 180, dC = 5 * kPi / 180;
    std::vector<FluxCell> cells;
    for (int i = 0; i < 180; ++i) {
        const double g = (i + 0.5) * dGamma;
        const double omega = (std::cos(i * dGamma) - std::cos((i + 1) * dGamma)) * dC;
        for (int j = 0; j < 72; ++j) {
            const double c = (j + 0.5) * dC;
            const Vec3 local(std::sin(g) * std::cos(c), std::sin(g) * std::sin(c), std::cos(g));
            const double flux = p.intensityToward(local.x, local.y, local.z) * omega;
            if (flux > 0) cells.push_back({local.x * c0 + local.y * c90 + local.z * nadir, flux});
        }
    }
    return cells;
}

/// Where a luminaire's direct light first lands, lm: the floor (the plane at the eye), the
/// walls between it and the luminaire plane, the ceiling.
struct DirectFlux {
    double floor = 0, walls = 0, ceiling = 0;
    DirectFlux operator+(const DirectFlux& o) const { return {floor + o.floor, walls + o.walls, ceiling + o.ceiling}; }
};

/// The luminaire grid over the room's ceiling: positions (t across, r along), m.
std::vector<glm::dvec2> luminaireGrid(double width, double depth, double s) {
    const int half = static_cast<int>(std::lround(width / s / 2)), rows = static_cast<int>(std::lround(depth / s));
    std::vector<glm::dvec2> out;
    for (int k = 0; k < rows; ++k)
        for (int i = -half; i < half; ++i) out.emplace_back((i + 0.5) * s, (k + 0.5) * s);
    return out;
}

}  // namespace

WallTransferFactors wallTransferFactors(double x, double y, double h, const RoomReflectances& rho) {
    // Surfaces 0 floor, 1 walls, 2 ceiling; F[i][j] the form factor from i to j.
    const double floorArea = x * y, wallArea = 2 * h * (x + y);
    const double fc = parallelRectangles(x, y, h), fw = 1 - fc, wf = floorArea * fw / wallArea;
    const double F[3][3] = {{0, fw, fc}, {wf, 1 - 2 * wf, wf}, {fc, fw, 0}};
    const double area[3] = {floorArea, wallArea, floorArea}, r[3] = {rho.floor, rho.walls, rho.ceiling};
    double out[3];
    for (int s = 0; s < 3; ++s) {
        // Exitance M_i = ρ_i (E⁰_i + Σ_j F_ij M_j), E⁰ one lumen on surface s: (I − ρF) M = ρ E⁰,
        // solved by Gaussian elimination.
        double a[3][4];
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 3; ++j) a[i][j] = (i == j ? 1 : 0) - r[i] * F[i][j];
            a[i][3] = i == s ? r[i] / area[i] : 0;
        }
        for (int i = 0; i < 3; ++i)
            for (int k = 0; k < 3; ++k) {
                if (k == i) continue;
                const double f = a[k][i] / a[i][i];
                for (int j = i; j < 4; ++j) a[k][j] -= f * a[i][j];
            }
        double wallIllum = 0;  // the walls' interreflected illuminance, Σ_j F_Wj M_j
        for (int j = 0; j < 3; ++j) wallIllum += F[1][j] * a[j][3] / a[j][j];
        out[s] = wallIllum * wallArea;
    }
    return {out[0], out[1], out[2]};
}

namespace {

/// What a standard room shows the observer, whatever its reflectances: the luminaires'
/// direct flux on its surfaces and the luminaires within the field the formula counts.
struct RoomView {
    double width = 0, depth = 0;  ///< m
    DirectFlux direct;            ///< lm, all luminaires
    std::vector<GlareSource> sources;
    int luminaires = 0;
};

/// The room with the luminaire grid of `spacing` × H, the distribution turned into the
/// room as `cells` (fluxCells with C0 along `c0`: crosswise toward the observer, endwise
/// across the line of sight).
RoomView roomView(const scene::Photometry& p, const UgrTableRoom& room, const Vec3& c0,
                  const std::vector<FluxCell>& cells, double spacing) {
    const double H = kUgrTableHeight;
    RoomView v;
    v.width = room.x * H, v.depth = room.y * H;
    const Vec3 nadir(0, 0, -1), c90 = glm::cross(-nadir, c0);
    const std::vector<glm::dvec2> grid = luminaireGrid(v.width, v.depth, spacing * H);
    v.luminaires = static_cast<int>(grid.size());

    // The direct flux, over every luminaire (the eye plane z = 0, the luminaires at z = H).
    v.direct = tbb::parallel_reduce(
        tbb::blocked_range<size_t>(0, grid.size()), DirectFlux{},
        [&](const tbb::blocked_range<size_t>& range, DirectFlux sum) {
            for (size_t k = range.begin(); k < range.end(); ++k)
                for (const FluxCell& cell : cells) {
                    const Vec3& d = cell.direction;
                    if (d.z >= 0) {
                        sum.ceiling += cell.flux;
                        continue;
                    }
                    const double s = H / -d.z, x = grid[k].x + s * d.x, y = grid[k].y + s * d.y;
                    (std::abs(x) <= v.width / 2 && y >= 0 && y <= v.depth ? sum.floor : sum.walls) += cell.flux;
                }
            return sum;
        },
        [](const DirectFlux& a, const DirectFlux& b) { return a + b; });

    // The luminaires as the eye at (0, 0, 0) sees them, looking along y with z up.
    for (const glm::dvec2& at : grid) {
        const double T = std::abs(at.x), R = at.y;
        const double horizontal = std::hypot(T, R);
        if (T / R > kMaxLateralRatio || std::atan2(horizontal, H) > kMaxGammaDeg * kPi / 180) continue;
        const Vec3 toLuminaire(at.x, at.y, H);
        const double r = glm::length(toLuminaire);
        const Vec3 w = -toLuminaire / r;  // from the luminaire to the eye
        const Vec3 local(glm::dot(w, c0), glm::dot(w, c90), glm::dot(w, nadir));
        const double area = projectedLuminousArea(p, local);
        const double intensity = p.intensityToward(local.x, local.y, local.z);
        GlareSource s;
        s.direction = Vec3(at.x, H, at.y) / r;  // view frame: x right, y up, z along the line of sight
        s.positionIndex = positionIndex(s.direction);
        if (!(intensity > 0) || s.positionIndex > kMaxPositionIndex) continue;
        s.luminance = intensity / area;
        s.solidAngle = area / (r * r);
        v.sources.push_back(s);
    }
    return v;
}

/// The room's entry for one set of reflectances: L_b = E_W,ind / π from the direct flux and
/// the walls' transfer factors, over the walls' area 2H(X + Y).
UgrTableEntry entryOf(const RoomView& v, const RoomReflectances& rho) {
    const double H = kUgrTableHeight;
    const WallTransferFactors ft = wallTransferFactors(v.width, v.depth, H, rho);
    const double wallArea = 2 * H * (v.width + v.depth);
    UgrTableEntry out;
    out.backgroundLuminance =
        (v.direct.floor * ft.fromFloor + v.direct.walls * ft.fromWalls + v.direct.ceiling * ft.fromCeiling) / wallArea /
        kPi;
    out.luminaires = v.luminaires;
    out.counted = static_cast<int>(v.sources.size());
    out.ugr = unifiedGlareRating(out.backgroundLuminance, v.sources);
    return out;
}

/// C0 crosswise (along the line of sight, toward the observer) or endwise (across it).
Vec3 c0Of(bool endwise) { return endwise ? Vec3(1, 0, 0) : Vec3(0, -1, 0); }

}  // namespace

UgrTableEntry ugrTableEntry(const scene::Photometry& p, const UgrTableRoom& room, const RoomReflectances& rho,
                            bool endwise, double spacing) {
    const Vec3 c0 = c0Of(endwise);
    return entryOf(roomView(p, room, c0, fluxCells(p, c0), spacing), rho);
}

UgrTable ugrTable(const scene::Photometry& p, double spacing) {
    if (!(projectedLuminousArea(p, Vec3(0, 0, 1)) > 0))
        throw InputError(placeMessage(p.file, "", "the file gives no luminous area (width, length and height 0): a "
                                                  "luminaire's luminance, and so its UGR, needs one"));
    UgrTable t;
    t.spacing = spacing;
    t.flux = p.integratedFlux();
    t.values.resize(kUgrTableRooms.size());
    // Each room and view once: the reflectances change only the background.
    for (int view = 0; view < 2; ++view) {
        const Vec3 c0 = c0Of(view == 1);
        const std::vector<FluxCell> cells = fluxCells(p, c0);
        for (size_t i = 0; i < kUgrTableRooms.size(); ++i) {
            const RoomView v = roomView(p, kUgrTableRooms[i], c0, cells, spacing);
            for (size_t k = 0; k < kUgrTableReflectances.size(); ++k)
                t.values[i][static_cast<size_t>(view) * 5 + k] = entryOf(v, kUgrTableReflectances[k]).ugr;
        }
    }
    return t;
}

std::string ugrTableText(const UgrTable& table, const scene::Photometry& p) {
    std::string s = fmt::format("UGR table (CIE 190 tabular method) for {}\n", p.file);
    s += fmt::format("luminaire flux {:.1f} lm; luminous area ", table.flux);
    s += p.round ? fmt::format("diameter {:.3f} m", p.width)
                 : fmt::format("{:.3f} m along C0 x {:.3f} m along C90", p.length, p.width);
    if (p.height > 0) s += fmt::format(", height {:.3f} m", p.height);
    s += fmt::format("; spacing {:g} H; observer seated (eye {:g} m) at the middle of a wall\n", table.spacing,
                     kUgrTableEyeHeight);
    auto line = [&](const char* name, auto get) {
        s += fmt::format("{:<14}", name);
        for (int view = 0; view < 2; ++view) {
            for (const auto& r : kUgrTableReflectances) s += fmt::format("{:>6.2f}", get(r));
            s += "  ";
        }
        s += "\n";
    };
    line("ceiling", [](const RoomReflectances& r) { return r.ceiling; });
    line("walls", [](const RoomReflectances& r) { return r.walls; });
    line("floor", [](const RoomReflectances& r) { return r.floor; });
    s += fmt::format("{:<14}{:<32}{}\n", "room X    Y", "viewed crosswise", "viewed endwise");
    for (size_t i = 0; i < table.values.size(); ++i) {
        s += fmt::format("{:>6}H {:>3}H  ", kUgrTableRooms[i].x, kUgrTableRooms[i].y);
        for (int k = 0; k < 10; ++k) {
            const auto& v = table.values[i][k];
            s += v ? fmt::format("{:>6.1f}", *v) : fmt::format("{:>6}", "-");
            if (k == 4) s += "  ";
        }
        s += "\n";
    }
    s += "For a luminaire of another flux F (lm), add 8 log10(F / " + fmt::format("{:.1f}", table.flux) + ").\n";
    return s;
}

std::string ugrTableCsv(const UgrTable& table) {
    std::string s = "x_h,y_h";
    for (const char* view : {"cross", "end"})
        for (const auto& r : kUgrTableReflectances)
            s += fmt::format(",{}_{:.0f}_{:.0f}_{:.0f}", view, 100 * r.ceiling, 100 * r.walls, 100 * r.floor);
    s += "\n";
    for (size_t i = 0; i < table.values.size(); ++i) {
        s += fmt::format("{},{}", kUgrTableRooms[i].x, kUgrTableRooms[i].y);
        for (const auto& v : table.values[i]) s += v ? fmt::format(",{:.2f}", *v) : std::string(",");
        s += "\n";
    }
    return s;
}

}  // namespace rayrad::app
