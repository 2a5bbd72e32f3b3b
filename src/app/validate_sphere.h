// rayrad validate sphere: the paper's Table 4 (sphere with mirrors) on this machine.
#pragma once

#include <string>

namespace rayrad::app {

struct ValidateSphereOptions {
    std::string sceneDir = "scenes/sphere";
    std::string outDir = "out/validate-sphere";
    bool quick = false;   ///< the 768-triangle sphere only
    int threads = 0;
};

/// SPH2 and SPH4, the paper's 768-triangle sphere and a 12 288-triangle one, clusters
/// on and off: total-illuminance error at A, B, C (gathered and vertex) and time, as a
/// Markdown table and results.csv in outDir. Returns the exit code.
int validateSphere(const ValidateSphereOptions& options);

}  // namespace rayrad::app
