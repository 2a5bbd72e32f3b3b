// What a termination signal (SIGTERM from a batch system's time limit, SIGINT from Ctrl-C,
// SIGHUP from a closed terminal) does to a run's outputs: it removes the temporary files
// being written, and during the renames that put outputs in place it waits until they
// are undone, so old outputs stay as they were. The process then ends as the signal ends
// it (exit status 128 + N in a shell).
#pragma once

#include <string>
#include <vector>

namespace rayrad {

/// Installs the handlers for SIGTERM, SIGINT and SIGHUP; called once, first thing in main.
void installTerminationCleanup();

/// Files a termination signal removes while this object lives (one at a time per process:
/// the outputs of a commit). `paths` must not change while it is registered.
class TerminationCleanup {
  public:
    explicit TerminationCleanup(const std::vector<std::string>& paths);
    ~TerminationCleanup();
    TerminationCleanup(const TerminationCleanup&) = delete;
    TerminationCleanup& operator=(const TerminationCleanup&) = delete;

    /// From now on a termination signal is held back (its number kept), so a series of
    /// renames is either finished or undone before the process ends.
    void holdSignals();
    /// The signal held back since holdSignals(), or 0.
    int heldSignal() const;
    /// Ends the hold: a signal held back now removes the files and ends the process.
    void releaseSignals();
};

}  // namespace rayrad
