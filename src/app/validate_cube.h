// rayrad validate cube: the paper's Tables 2 and 3 (and ablations) measured on this machine.
#pragma once

#include <string>

namespace rayrad::app {

struct ValidateOptions {
    std::string scene = "scenes/cube/cube.json";
    std::string outDir = "out/validate-cube";
    bool quick = false;   ///< a subset at 1 200 / 4 800 triangles, for CI
    int threads = 0;
};

/// Runs every configuration as a child `rayrad solve` (so each has its own peak memory),
/// prints Markdown tables beside the paper's figures, and writes results.csv, one
/// convergence CSV per run and PNG plots of error against time (the paper's Figs. 3–4)
/// into outDir. Returns the exit code.
int validateCube(const ValidateOptions& options);

}  // namespace rayrad::app
