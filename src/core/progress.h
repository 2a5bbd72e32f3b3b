// A one-line progress display on stderr for long work (only when stderr is a terminal).
#pragma once

#include <chrono>
#include <mutex>
#include <string>

namespace rayrad {

/// Rewrites one status line on stderr at most a few times a second. Silent when stderr
/// is not a terminal or when quiet, so logs and CI output stay clean. update() may be
/// called from several threads at once (a parallel stage's workers).
class Progress {
  public:
    explicit Progress(std::string label, bool quiet = false);
    ~Progress();
    /// `fraction` in [0, 1] (clamped); `detail` is shown after the percentage.
    void update(double fraction, const std::string& detail = {});
    void finish();

  private:
    std::string m_label;
    const bool m_enabled;
    std::mutex m_mutex;  ///< guards the line and the fields below
    bool m_shown = false;
    std::chrono::steady_clock::time_point m_last;
};

}  // namespace rayrad
