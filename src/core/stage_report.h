// Wall time, CPU time and peak memory of each pipeline stage, printed on stderr at the end of a run.
#pragma once

#include <chrono>
#include <string>
#include <vector>

namespace rayrad {

/// Peak resident set size of this process so far, in bytes (VmHWM; 0 if unknown).
size_t peakMemoryBytes();

/// CPU seconds (user + sys) this process has used so far, all threads.
double processCpuSeconds();

/// Records, for each stage the pipeline ran, its wall time, CPU time (user + sys, all
/// threads) and the peak memory after it.
class StageReport {
  public:
    struct Stage {
        std::string name;
        double seconds = 0;     ///< wall
        double cpuSeconds = 0;  ///< user + sys
        size_t peakBytes = 0;
    };

    /// Starts timing a stage; the previous one (if any) ends here.
    void begin(const std::string& name);
    /// Ends the current stage.
    void end();

    const std::vector<Stage>& stages() const { return m_stages; }
    double totalSeconds() const;
    double totalCpuSeconds() const;
    std::string toString() const;

  private:
    std::vector<Stage> m_stages;
    std::chrono::steady_clock::time_point m_start;
    double m_cpuStart = 0;
    bool m_running = false;
};

}  // namespace rayrad
