#include <app/validation_checks.h>

#include <fmt/format.h>

#include <chrono>
#include <cmath>

namespace rayrad::app {

Check timed(const std::string& what, double bound, const std::string& unit, const std::function<double()>& run) {
    const auto start = std::chrono::steady_clock::now();
    const double error = run();
    return {what, error, bound, unit, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()};
}

int printChecks(const std::vector<Check>& checks) {
    fmt::print("| check | error | bound | run time |\n|---|---:|---:|---:|\n");
    bool ok = true;
    for (const auto& c : checks) {
        const bool within = std::abs(c.error) <= c.bound;
        ok &= within;
        fmt::print("| {} | {:+.4f} {} | {} {} | {:.3f} s |{}\n", c.what, c.error, c.unit, c.bound, c.unit, c.seconds,
                   within ? "" : " **beyond the bound**");
    }
    return ok ? 0 : 1;
}

}  // namespace rayrad::app
