// A validation's checks: each an error against a reference, its bound and its run time,
// printed as one Markdown table (rayrad validate daylight, validate glare).
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace rayrad::app {

struct Check {
    std::string what;
    double error = 0;  ///< in the unit of `unit`
    double bound = 0;
    std::string unit;  ///< "°", "%", "UGR" …
    double seconds = 0;
};

/// Times `run`, which returns the error.
Check timed(const std::string& what, double bound, const std::string& unit, const std::function<double()>& run);

/// The table (check, error, bound, run time), a check beyond its bound marked; the exit
/// code: 0 when every error is within its bound, else 1.
int printChecks(const std::vector<Check>& checks);

}  // namespace rayrad::app
