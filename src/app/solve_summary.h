// The end-of-run summary on stderr: patches, shots, clusters, transfers, energy account.
#pragma once

#include <app/pipeline.h>

namespace rayrad::app {

/// Prints the solve's counts, its convergence, its cluster and transfer statistics, the
/// energy account (emitted, absorbed, unshot, not accounted) and the closure line.
void printSolveSummary(const PipelineRun& run);

}  // namespace rayrad::app
