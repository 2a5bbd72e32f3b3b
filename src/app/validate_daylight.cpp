#include <app/validate_daylight.h>

#include <app/validation_checks.h>
#include <radiosity/radiosity.h>
#include <raytrace/embree_scene.h>
#include <scene/daylight/glazing.h>
#include <scene/daylight/perez.h>
#include <scene/daylight/sky.h>
#include <scene/daylight/sun_position.h>
#include <scene/scene.h>
#include <scene/scene_parser.h>

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace rayrad::app {

namespace {

/// A scene with one 2 × 2 m opening in the plane given by its corners (CCW seen from the
/// room), a far floor, z up, and the sky and sun as JSON; DirectLight over it.
struct OpeningScene {
    scene::Scene scene;
    radiosity::PatchMesh mesh;
    std::unique_ptr<raytrace::EmbreeScene> embree;
    std::unique_ptr<radiosity::DirectLight> lights;
    OpeningScene(const std::string& corners, const std::string& daylight, double transmittance = 1) {
        const std::string json = R"({"materials": {"m": {"reflectance": 0.5},
            "hole": {"type": "opening", "transmittance": )" +
                                 fmt::format("{}", transmittance) + R"(}},
            "objects": [{"type": "quad", "material": "m", "vertices": [[-50,-50,-10],[50,-50,-10],[50,50,-10],[-50,50,-10]]},
                        {"type": "quad", "material": "hole", "vertices": )" +
                                 corners + R"(}],
            "daylight": {"up": [0, 0, 1], "north": [0, 1, 0], )" +
                                 daylight + "}}";
        scene = scene::buildScene(scene::parseScene(json, "validate-daylight.json"));
        mesh = radiosity::prepareMesh(scene, {});
        embree = std::make_unique<raytrace::EmbreeScene>(mesh, 1e-5 * scene.diagonal());
        lights = std::make_unique<radiosity::DirectLight>(scene);
    }
    double at(const Vec3& x, const Vec3& n) const {
        return luminance(lights->illuminance(x, n, *embree, scene.render.sensorAreaLightSamples, nullptr));
    }
};

/// F from a point to a parallel a × b rectangle with a corner straight above it at height h.
double cornerFormFactor(double a, double b, double h) {
    const double X = a / h, Y = b / h;
    return (X / std::sqrt(1 + X * X) * std::atan(Y / std::sqrt(1 + X * X)) +
            Y / std::sqrt(1 + Y * Y) * std::atan(X / std::sqrt(1 + Y * Y))) /
           (2 * kPi);
}

/// ∫ L(ω) cosθ_x cosθ_y / r² dA over a 2 × 2 m square (centre c, unit normal nY facing x,
/// sides along s1, s2) seen from x with normal n, midpoint rule on an 1 200² grid.
double squareQuadrature(const Vec3& x, const Vec3& n, const Vec3& c, const Vec3& nY, const Vec3& s1, const Vec3& s2,
                        const std::function<double(const Vec3&)>& L) {
    constexpr int kN = 1200;
    const double cell = 2.0 / kN;
    double sum = 0;
    for (int i = 0; i < kN; ++i)
        for (int j = 0; j < kN; ++j) {
            const Vec3 y = c + (-1 + (i + 0.5) * cell) * s1 + (-1 + (j + 0.5) * cell) * s2;
            const Vec3 d = y - x;
            const double r2 = glm::dot(d, d), r = std::sqrt(r2);
            const double cx = glm::dot(n, d) / r, cy = -glm::dot(nY, d) / r;
            if (cx > 0 && cy > 0) sum += L(d / r) * cx * cy / r2;
        }
    return sum * cell * cell;
}

/// The CIE standard general sky's L / L_z, written out from ISO 15469 (not the code under test).
double standardSky(const scene::CieSkyParameters& p, double Z, double chi, double Zs) {
    auto phi = [&](double z) { return z < kPi / 2 ? 1 + p.a * std::exp(p.b / std::cos(z)) : 1.0; };
    auto f = [&](double x) {
        return 1 + p.c * (std::exp(p.d * x) - std::exp(p.d * kPi / 2)) + p.e * std::cos(x) * std::cos(x);
    };
    return f(chi) * phi(Z) / (f(Zs) * phi(0));
}

}  // namespace

double skyOnHorizontalPlane(const scene::Daylight& d) {
    const int nz = 900, na = 1800;
    double sum = 0;
    for (int i = 0; i < nz; ++i) {
        const double z = (i + 0.5) * (kPi / 2) / nz;
        for (int j = 0; j < na; ++j) {
            const double a = (j + 0.5) * 2 * kPi / na;
            const Vec3 local(std::sin(z) * std::sin(a), std::sin(z) * std::cos(a), std::cos(z));
            sum += d.luminance(d.toWorld(local)) * std::cos(z) * std::sin(z);
        }
    }
    return sum * (kPi / 2 / nz) * (2 * kPi / na);
}

int validateDaylight() {
    std::vector<Check> checks;

    // The SPA paper's example: 17 October 2003, 12:30:30 at UTC−7, Golden, Colorado.
    scene::LocalTime t{2003, 10, 17, 12, 30, 30, -7};
    scene::Site site{39.742476, -105.1786, 1830.14, 820, 11, 67};
    scene::SunPosition sun;
    checks.push_back(timed("sun position: zenith angle, SPA worked example (50.11162°)", 0.01, "°", [&] {
        sun = scene::sunPosition(t, site);
        return sun.zenithDeg() - 50.11162;
    }));
    checks.push_back(
        timed("sun position: azimuth, SPA worked example (194.34024°)", 0.01, "°", [&] { return sun.azimuthDeg - 194.34024; }));

    // The 15 skies at sky points all round, the sun at 40° altitude, azimuth 135°.
    checks.push_back(timed("15 CIE standard skies: L/L_z at 15 × 72 sky points", 0.1, "%", [&] {
        const double alt = 40 * kPi / 180, az = 135 * kPi / 180;
        const Vec3 sunLocal(std::sin(az) * std::cos(alt), std::cos(az) * std::cos(alt), std::sin(alt));
        double worst = 0;
        for (int type = 1; type <= 15; ++type) {
            const scene::SkyDistribution sky(scene::SkyKind::CieStandard, type, kPi / 2 - alt);
            for (int i = 0; i < 6; ++i)
                for (int j = 0; j < 12; ++j) {
                    const double Z = (i * 15 + 2) * kPi / 180, a = j * 30 * kPi / 180;
                    const Vec3 w(std::sin(a) * std::sin(Z), std::cos(a) * std::sin(Z), std::cos(Z));
                    const double chi = std::acos(std::clamp(glm::dot(w, sunLocal), -1.0, 1.0));
                    const double ref = standardSky(scene::cieSkyParameters(type), Z, chi, kPi / 2 - alt);
                    worst = std::max(worst, std::abs(sky.relative(w, sunLocal) / ref - 1));
                }
        }
        return 100 * worst;
    }));

    // A uniform sky through a 2 × 2 m roof opening 3 m up: E = π L F.
    const std::string roof = "[[-1,-1,3],[-1,1,3],[1,1,3],[1,-1,3]]";
    checks.push_back(timed("uniform sky through a roof opening, below its centre: π L F", 0.5, "%", [&] {
        OpeningScene s(roof, R"("sky": {"type": "uniform", "zenith_luminance": 1000})");
        const double ref = kPi * 1000 * 4 * cornerFormFactor(1, 1, 3);
        return 100 * (s.at({0, 0, 0}, {0, 0, 1}) / ref - 1);
    }));
    checks.push_back(timed("uniform sky through a roof opening, 2.5 m aside: π L F", 0.5, "%", [&] {
        OpeningScene s(roof, R"("sky": {"type": "uniform", "zenith_luminance": 1000})");
        const double ref = kPi * 1000 * 2 * (cornerFormFactor(3.5, 1, 3) - cornerFormFactor(1.5, 1, 3));
        return 100 * (s.at({2.5, 0, 0}, {0, 0, 1}) / ref - 1);
    }));
    // The traditional overcast sky: L = L_z (1 + 2 cos Z) / 3, the ground ρ_g E_h / π (E_h = 7π/9 L_z).
    auto overcast = [](const Vec3& w) { return w.z >= 0 ? 3000 * (1 + 2 * w.z) / 3 : 0.2 * 3000 * 7 / 9; };
    checks.push_back(timed("CIE overcast sky through a roof opening, 2.5 m aside: quadrature", 0.5, "%", [&] {
        OpeningScene s(roof, R"("sky": {"type": "cie_overcast", "zenith_luminance": 3000})");
        const double ref = squareQuadrature({2.5, 0, 0}, {0, 0, 1}, {0, 0, 3}, {0, 0, -1}, {1, 0, 0}, {0, 1, 0}, overcast);
        return 100 * (s.at({2.5, 0, 0}, {0, 0, 1}) / ref - 1);
    }));
    // A vertical 2 × 2 m window (centre 1.5 m up, facing −y into the room), a point 2 m in
    // front of it at 0.8 m on a horizontal and on a vertical plane; sky and ground.
    const std::string window = "[[-1,0,0.5],[1,0,0.5],[1,0,2.5],[-1,0,2.5]]";
    for (const auto& [what, n] : {std::pair<std::string, Vec3>{"horizontal", {0, 0, 1}}, {"vertical", {0, 1, 0}}}) {
        checks.push_back(
            timed("CIE overcast sky and ground through a vertical window, " + what + " plane: quadrature", 0.5, "%",
                  [&, n = n] {
                      OpeningScene s(window, R"("sky": {"type": "cie_overcast", "zenith_luminance": 3000},
                                                "ground_reflectance": 0.2)");
                      const double ref = squareQuadrature({0.3, -2, 0.8}, n, {0, 0, 1.5}, {0, -1, 0}, {1, 0, 0},
                                                          {0, 0, 1}, overcast);
                      return 100 * (s.at({0.3, -2, 0.8}, n) / ref - 1);
                  }));
    }
    checks.push_back(timed("the same window glazed (τ_n 0.8, clear glass), vertical plane: quadrature", 0.5, "%", [&] {
        OpeningScene s(window, R"("sky": {"type": "cie_overcast", "zenith_luminance": 3000}, "ground_reflectance": 0.2)",
                       0.8);
        const double ref =
            squareQuadrature({0.3, -2, 0.8}, {0, 1, 0}, {0, 0, 1.5}, {0, -1, 0}, {1, 0, 0}, {0, 0, 1}, [&](const Vec3& w) {
                return overcast(w) * scene::glazingTransmittance(0.8, w.y);  // the window's normal is −y
            });
        return 100 * (s.at({0.3, -2, 0.8}, {0, 1, 0}) / ref - 1);
    }));
    // The sun at 35° altitude, azimuth 200°, 80 000 lx, on a plane tilted 30° toward the south.
    checks.push_back(timed("the sun on a plane tilted 30° to the south: E_n cos i", 0.5, "%", [&] {
        OpeningScene s(roof, R"("sky": {"type": "uniform", "zenith_luminance": 1},
                                "sun": {"altitude": 35, "azimuth": 200, "direct_normal_illuminance": 80000})");
        const double alt = 35 * kPi / 180, az = 200 * kPi / 180, tilt = 30 * kPi / 180;
        const Vec3 toSun(std::sin(az) * std::cos(alt), std::cos(az) * std::cos(alt), std::sin(alt));
        const Vec3 n(0, -std::sin(tilt), std::cos(tilt));  // north is +y: tilted toward −y
        const Vec3 x(20, 0, 0);                              // outdoors, away from the opening
        const double ref = 80000 * glm::dot(toSun, n);  // the sky reaches outdoors only through openings: none
        return 100 * (s.at(x, n) / ref - 1);
    }));
    // A clear hour (Perez all-weather sky, sun at 35°, south): the sky's horizontal
    // illuminance by a quadrature in zenith angle and azimuth against the E_dh the Perez
    // efficacy gives; and the same hour given as illuminances, its irradiances found back.
    checks.push_back(timed("Perez sky, a clear hour: ∫ L cos Z dω (quadrature) against E_dh", 0.1, "%", [&] {
        OpeningScene s(roof, R"("sky": {"type": "perez", "direct_normal_irradiance": 750,
                                        "diffuse_horizontal_irradiance": 110}, "sun": {"altitude": 35, "azimuth": 180})");
        const scene::Daylight& d = *s.scene.daylight;
        return 100 * (skyOnHorizontalPlane(d) / d.perez->diffuseHorizontalIlluminance - 1);
    }));
    checks.push_back(timed("Perez sky, the hour given as illuminances: D found back (Perez 1990 efficacy)", 0.5, "%", [&] {
        const scene::PerezConditions c{55 * kPi / 180, 172, 11};
        const auto hour = scene::perezFromIrradiance(750, 110, c);
        const auto back = scene::perezFromIlluminance(hour.directNormalIlluminance, hour.diffuseHorizontalIlluminance, c);
        return 100 * (back.diffuseHorizontalIrradiance / 110 - 1);
    }));

    return printChecks(checks);
}

}  // namespace rayrad::app
