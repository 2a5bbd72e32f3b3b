#include <radiosity/shooting/closure.h>

#include <core/random.h>

#include <algorithm>
#include <cmath>

namespace rayrad::radiosity {

double escapeFraction(const PatchMesh& mesh, const Visibility& vis, double farAway, const std::vector<double>& weight,
                      int rays) {
    double total = 0;
    for (double w : weight) total += std::max(0.0, w);
    if (mesh.patches.empty() || rays <= 0 || !(total > 0)) return 0.0;
    Random rng(7, 0);
    int escaped = 0;
    size_t i = 0;
    double passed = 0;  // weight of the patches before i
    for (int k = 0; k < rays; ++k) {
        // Patch by stratified weight: the one where (k + ½)/rays of the total falls.
        double target = (k + 0.5) / rays * total;
        while (i + 1 < mesh.patches.size() && passed + std::max(0.0, weight[i]) < target)
            passed += std::max(0.0, weight[i++]);
        const Patch& p = mesh.patches[i];
        // A random point of the triangle, a cosine-distributed direction about its normal.
        double a = rng.nextDouble(), b = rng.nextDouble();
        if (a + b > 1) a = 1 - a, b = 1 - b;
        Vec3 x = mesh.corner(p, 0) + a * (mesh.corner(p, 1) - mesh.corner(p, 0)) +
                 b * (mesh.corner(p, 2) - mesh.corner(p, 0));
        double u = rng.nextDouble(), phi = 2 * kPi * rng.nextDouble();
        double r = std::sqrt(u);
        Vec3 t = std::abs(p.normal.x) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
        Vec3 e1 = glm::normalize(glm::cross(p.normal, t)), e2 = glm::cross(p.normal, e1);
        Vec3 dir = r * std::cos(phi) * e1 + r * std::sin(phi) * e2 + std::sqrt(std::max(0.0, 1 - u)) * p.normal;
        escaped += vis.visible(x, x + farAway * dir);
    }
    return static_cast<double>(escaped) / rays;
}

}  // namespace rayrad::radiosity
